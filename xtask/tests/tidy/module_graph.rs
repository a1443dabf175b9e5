//! A chapter crate's module graph, parsed with `syn` (not matched as text):
//! its modules from `lib.rs` down through every `mod` declaration, and, per
//! module, every path its non-test code names (use trees, types, traits,
//! expressions, patterns, macros), resolved to `crate::…` or to an external
//! crate. The tidy rule "domains never import agents" is checked on it.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use syn::visit::Visit;

/// A module: its path from the crate root (`["maze", "env"]`), the file it
/// lives in, and the paths its non-test code names.
#[derive(Debug, Default)]
pub struct Module {
    /// The file the module's items are in.
    pub file: PathBuf,
    /// Every path named, resolved: `crate::a::b` for the crate's own items,
    /// `rlfd_rl::…` for an external crate; unresolvable relative names are
    /// kept as written.
    pub names: Vec<Vec<String>>,
    /// The traits this module implements for its types (last segment, e.g. `Environment`),
    /// with the trait's resolved path.
    pub implements: Vec<Vec<String>>,
}

/// The crate: module path → module.
pub type Graph = BTreeMap<Vec<String>, Module>;

/// Whether attributes mark an item as test-only (`#[cfg(test)]`, `#[test]`).
fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        (a.path().is_ident("cfg") && a.meta.require_list().is_ok_and(|l| l.tokens.to_string().contains("test")))
            || a.path().is_ident("test")
    })
}

/// `#[path = "…"]` on a module declaration.
fn path_attr(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find(|a| a.path().is_ident("path")).and_then(|a| match &a.meta {
        syn::Meta::NameValue(nv) => match &nv.value {
            syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) => Some(s.value()),
            _ => None,
        },
        _ => None,
    })
}

/// Parses the crate whose root is `lib`.
pub fn parse_crate(lib: &Path) -> Graph {
    let mut graph = Graph::new();
    let dir = lib.parent().unwrap().to_path_buf();
    parse_file(lib, Vec::new(), dir, &mut graph);
    graph
}

fn parse_file(file: &Path, module: Vec<String>, child_dir: PathBuf, graph: &mut Graph) {
    let text = fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    let ast = syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
    parse_items(&ast.items, file, module, child_dir, graph);
}

fn parse_items(items: &[syn::Item], file: &Path, module: Vec<String>, child_dir: PathBuf, graph: &mut Graph) {
    let mut names = Names { module: module.clone(), names: Vec::new(), implements: Vec::new() };
    for item in items {
        match item {
            syn::Item::Mod(m) if is_test(&m.attrs) => {}
            syn::Item::Mod(m) => {
                let name = m.ident.to_string();
                let mut child = module.clone();
                child.push(name.clone());
                match &m.content {
                    Some((_, inner)) => parse_items(inner, file, child, child_dir.join(&name), graph),
                    None => {
                        let path = match path_attr(&m.attrs) {
                            Some(p) => file.parent().unwrap().join(p),
                            None if child_dir.join(format!("{name}.rs")).exists() => {
                                child_dir.join(format!("{name}.rs"))
                            }
                            None => child_dir.join(&name).join("mod.rs"),
                        };
                        parse_file(&path, child, child_dir.join(&name), graph);
                    }
                }
            }
            item if is_test(item_attrs(item)) => {}
            item => names.visit_item(item),
        }
    }
    let entry = graph.entry(module).or_default();
    entry.file = file.to_path_buf();
    entry.names.extend(names.names);
    entry.implements.extend(names.implements);
}

fn item_attrs(item: &syn::Item) -> &[syn::Attribute] {
    match item {
        syn::Item::Const(i) => &i.attrs,
        syn::Item::Enum(i) => &i.attrs,
        syn::Item::Fn(i) => &i.attrs,
        syn::Item::Impl(i) => &i.attrs,
        syn::Item::Static(i) => &i.attrs,
        syn::Item::Struct(i) => &i.attrs,
        syn::Item::Trait(i) => &i.attrs,
        syn::Item::Type(i) => &i.attrs,
        syn::Item::Use(i) => &i.attrs,
        syn::Item::Macro(i) => &i.attrs,
        _ => &[],
    }
}

/// Collects the paths a module names, resolved against its position.
struct Names {
    module: Vec<String>,
    names: Vec<Vec<String>>,
    implements: Vec<Vec<String>>,
}

impl Names {
    /// `crate::…`, `super::…`, `self::…` made absolute (`crate`, then the
    /// module path); anything else kept as written (an external crate, a
    /// prelude name, or a name brought in by a `use` that is itself recorded).
    fn resolve(&self, segments: Vec<String>) -> Vec<String> {
        let mut out = vec!["crate".to_string()];
        let mut rest = segments.as_slice();
        match rest.first().map(String::as_str) {
            Some("crate") => rest = &rest[1..],
            Some("self") => {
                out.extend(self.module.iter().cloned());
                rest = &rest[1..];
            }
            Some("super") => {
                let mut base = self.module.clone();
                while rest.first().map(String::as_str) == Some("super") {
                    base.pop();
                    rest = &rest[1..];
                }
                out.extend(base);
            }
            _ => return segments,
        }
        out.extend(rest.iter().cloned());
        out
    }

    fn use_tree(&mut self, prefix: &mut Vec<String>, tree: &syn::UseTree) {
        match tree {
            syn::UseTree::Path(p) => {
                prefix.push(p.ident.to_string());
                self.use_tree(prefix, &p.tree);
                prefix.pop();
            }
            syn::UseTree::Name(n) => {
                let mut full = prefix.clone();
                if n.ident != "self" {
                    full.push(n.ident.to_string());
                }
                self.names.push(self.resolve(full));
            }
            syn::UseTree::Rename(r) => {
                let mut full = prefix.clone();
                full.push(r.ident.to_string());
                self.names.push(self.resolve(full));
            }
            syn::UseTree::Glob(_) => self.names.push(self.resolve(prefix.clone())),
            syn::UseTree::Group(g) => {
                for t in &g.items {
                    self.use_tree(prefix, t);
                }
            }
        }
    }
}

impl<'ast> Visit<'ast> for Names {
    fn visit_item_use(&mut self, u: &'ast syn::ItemUse) {
        self.use_tree(&mut Vec::new(), &u.tree);
    }

    fn visit_item_impl(&mut self, i: &'ast syn::ItemImpl) {
        if is_test(&i.attrs) {
            return;
        }
        if let Some((_, path, _)) = &i.trait_ {
            let segments = path.segments.iter().map(|s| s.ident.to_string()).collect();
            self.implements.push(self.resolve(segments));
        }
        syn::visit::visit_item_impl(self, i);
    }

    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        if !is_test(&f.attrs) {
            syn::visit::visit_item_fn(self, f);
        }
    }

    fn visit_impl_item_fn(&mut self, f: &'ast syn::ImplItemFn) {
        if !is_test(&f.attrs) {
            syn::visit::visit_impl_item_fn(self, f);
        }
    }

    fn visit_path(&mut self, p: &'ast syn::Path) {
        let segments: Vec<String> = p.segments.iter().map(|s| s.ident.to_string()).collect();
        if segments.len() > 1 || p.leading_colon.is_some() {
            self.names.push(self.resolve(segments));
        }
        syn::visit::visit_path(self, p);
    }

    fn visit_macro(&mut self, m: &'ast syn::Macro) {
        // A macro's body is tokens; parse it as expressions where it is
        // (format!, vec!, assert! …) so paths inside are seen too.
        self.visit_path(&m.path);
        if let Ok(args) = m.parse_body_with(syn::punctuated::Punctuated::<syn::Expr, syn::Token![,]>::parse_terminated)
        {
            for e in &args {
                self.visit_expr(e);
            }
        }
    }
}
