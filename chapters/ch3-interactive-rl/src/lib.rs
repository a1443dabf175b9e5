//! Placeholder: this chapter is being built.
