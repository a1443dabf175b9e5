//! The seated Nao sorting objects into two cups (section 3.3.1): a
//! kinematic simulation of the table, the robot's state as the thesis
//! defines it, its camera in the small and the large state space, correct
//! sorting plans and the time each action takes.
//!
//! - [`action`]: the eleven actions and sets of them;
//! - [`kinematics`]: zones, hands, reach, which actions are legal, what they do;
//! - [`perception`]: the object descriptor in both spaces, the six objects, reading noise;
//! - [`state`]: the robot's view `(z_lh, z_rh, hand_o, I, o_z, o_p)` and its 360 / 6,480 states;
//! - [`world`]: the simulator ([`NaoSorting`]) with objects arriving in random order;
//! - [`plan`]: the shortest correct sorting plans the teacher judges by;
//! - [`timing`]: seconds per action, calibrated on the thesis's 9.8 s mean.
//!
//! What this is not: the learner or the teacher (chapter 3's crate holds
//! both). The crate depends on `rlfd-env` alone among the workspace's
//! libraries, so it cannot name an agent.

pub mod action;
pub mod kinematics;
pub mod perception;
pub mod plan;
pub mod state;
pub mod timing;
pub mod world;

pub use action::{Action, ActionKind, ActionSet, Hand};
pub use kinematics::{Cup, Effect, ObjectPosition, Physical, Zone};
pub use perception::{CATALOGUE, Features, ObjectClass, Perception, SHIFT_PROBABILITY, SortingObject, StateSpace};
pub use plan::SortingPlan;
pub use state::{Placement, SortingState, state_count};
pub use timing::Durations;
pub use world::{NaoSorting, Outcome, Sorted, random_walk_steps};
