//! The file import graph of `src/` and its strongly connected components: a circle of files
//! that import each other is one component, and the largest one in each room (top-level
//! module) says how tangled that room is.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use super::{module_of, rust_files, uses};

/// Every source file and the files of the same room it imports.
pub struct FileGraph {
    /// Paths relative to the crate root (`src/render/whitted.rs`).
    pub files: Vec<String>,
    /// The room (top-level module) of each file; `lib` and `main` for the roots.
    pub rooms: Vec<String>,
    /// `edges[a]` holds `b` when file `a` names an item of file `b` (same room, `a != b`).
    pub edges: Vec<BTreeSet<usize>>,
}

impl FileGraph {
    /// Reads every `.rs` file under `root/src`.
    pub fn of_crate(root: &Path) -> FileGraph {
        let src = root.join("src");
        let mut paths = Vec::new();
        rust_files(&src, &mut paths);
        let modules: Vec<Vec<String>> = paths.iter().map(|p| module_of(p, &src)).collect();
        let index: BTreeMap<Vec<String>, usize> = modules
            .iter()
            .enumerate()
            .map(|(i, m)| (m.clone(), i))
            .collect();
        let rooms: Vec<String> = paths
            .iter()
            .zip(&modules)
            .map(|(p, m)| {
                m.first().cloned().unwrap_or_else(|| {
                    p.file_stem()
                        .map_or_else(String::new, |s| s.to_string_lossy().into_owned())
                })
            })
            .collect();
        let mut edges = vec![BTreeSet::new(); paths.len()];
        for (a, path) in paths.iter().enumerate() {
            let text = std::fs::read_to_string(path).expect("read source");
            for u in uses(&text, &modules[a]) {
                // The longest module path that is a file owns the item.
                let owner = (1..=u.absolute.len())
                    .rev()
                    .find_map(|n| index.get(&u.absolute[..n]).copied());
                if let Some(b) = owner.filter(|&b| b != a && rooms[b] == rooms[a]) {
                    edges[a].insert(b);
                }
            }
        }
        let files = paths
            .iter()
            .map(|p| p.strip_prefix(root).unwrap_or(p).display().to_string())
            .collect();
        FileGraph {
            files,
            rooms,
            edges,
        }
    }

    /// The largest strongly connected component of each room, as file paths (sorted); a room
    /// without a circle reports a single file.
    pub fn largest_circles(&self) -> BTreeMap<String, Vec<String>> {
        let mut best: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for component in self.components() {
            let room = &self.rooms[component[0]];
            let mut names: Vec<String> = component.iter().map(|&f| self.files[f].clone()).collect();
            names.sort();
            let slot = best.entry(room.clone()).or_default();
            if names.len() > slot.len() {
                *slot = names;
            }
        }
        best
    }

    /// Tarjan's strongly connected components.
    fn components(&self) -> Vec<Vec<usize>> {
        struct State {
            next: usize,
            index: Vec<Option<usize>>,
            low: Vec<usize>,
            on_stack: Vec<bool>,
            stack: Vec<usize>,
            out: Vec<Vec<usize>>,
        }
        fn visit(g: &FileGraph, v: usize, s: &mut State) {
            s.index[v] = Some(s.next);
            s.low[v] = s.next;
            s.next += 1;
            s.stack.push(v);
            s.on_stack[v] = true;
            for &w in &g.edges[v] {
                match s.index[w] {
                    None => {
                        visit(g, w, s);
                        s.low[v] = s.low[v].min(s.low[w]);
                    }
                    Some(iw) if s.on_stack[w] => s.low[v] = s.low[v].min(iw),
                    Some(_) => {}
                }
            }
            if Some(s.low[v]) == s.index[v] {
                let mut component = Vec::new();
                while let Some(w) = s.stack.pop() {
                    s.on_stack[w] = false;
                    component.push(w);
                    if w == v {
                        break;
                    }
                }
                s.out.push(component);
            }
        }
        let n = self.files.len();
        let mut s = State {
            next: 0,
            index: vec![None; n],
            low: vec![0; n],
            on_stack: vec![false; n],
            stack: Vec::new(),
            out: Vec::new(),
        };
        for v in 0..n {
            if s.index[v].is_none() {
                visit(self, v, &mut s);
            }
        }
        s.out
    }
}
