//! What an evaluation is given: its budgets, the frame, the `--set` values and how it may
//! use threads (a leaf: every file of the evaluator may read it, it reads none of them).

/// Budgets that keep evaluation finite; each overrun is a clear error.
#[derive(Clone, Debug)]
pub struct EvalOptions {
    /// Total loop iterations over the whole evaluation.
    pub max_loop_iterations: u64,
    /// Depth of nested user-function calls.
    pub max_recursion_depth: u32,
    /// Objects in the scene.
    pub max_objects: u64,
    /// Elements in any one list.
    pub max_list_len: u64,
    /// Bytes in any one string.
    pub max_string_len: u64,
    /// Distinct files imported by one evaluation, all nesting levels together.
    pub max_imports: u32,
    /// Imports nested inside imports (a file that imports a file that imports ...).
    pub max_import_depth: u32,
    /// The frame evaluated: the built-in `frame` (`rtc render --frame N`).
    pub frame: i64,
    /// Frames per second: the built-in `time` is `frame / fps` (`rtc render --fps`).
    pub fps: f64,
    /// `--set NAME=VALUE` pairs overriding the scene file's `param` declarations.
    pub overrides: Vec<(String, String)>,
    /// Record where each object came from (`ir::Loaded::provenance`, for `rtc why`).
    pub provenance: bool,
    /// Whether long top-level loops may be evaluated on several threads (the result is the
    /// same either way).
    pub loop_parts: LoopParts,
    /// Bytes the whole load may hold: the evaluation's strings, lists and objects, then the
    /// textures and meshes the preparation loads (`ir::limits::Memory`, `--memory-budget`).
    pub max_memory: u64,
    /// When the evaluation must stop (`--time-limit`, counted from the start of the command):
    /// past it, the next loop step or call is `rtc::render::time_limit`.
    pub deadline: Option<std::time::Instant>,
}

/// Frames per second unless the command line says otherwise (film's rate).
pub const DEFAULT_FPS: f64 = 24.0;

impl Default for EvalOptions {
    fn default() -> EvalOptions {
        EvalOptions {
            max_loop_iterations: 50_000_000,
            max_recursion_depth: 256,
            max_objects: 10_000_000,
            max_list_len: 10_000_000,
            max_string_len: 10_000_000,
            max_imports: 10_000,
            max_import_depth: 64,
            frame: 0,
            fps: DEFAULT_FPS,
            overrides: Vec::new(),
            provenance: false,
            loop_parts: LoopParts::default(),
            max_memory: crate::ir::limits::DEFAULT_MEMORY_BUDGET,
            deadline: None,
        }
    }
}

/// How an evaluation may spread a scene file's long top-level `for` loops over threads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoopParts {
    /// Split a loop over up to `threads` threads (0: one per core) once its first iterations say
    /// that it pays.
    Auto {
        /// Most threads, the evaluating one included (0: the machine's cores).
        threads: usize,
    },
    /// Evaluate on one thread.
    Serial,
    /// Split every top-level loop of the scene file into this many parts from its first
    /// iteration, however short it is (for tests of the merge).
    Always(usize),
}

impl Default for LoopParts {
    fn default() -> LoopParts {
        LoopParts::Auto { threads: 0 }
    }
}

/// Runs `f` on a thread with the evaluation's large stack; `None` if the thread cannot start.
pub(crate) fn on_eval_stack<T: Send>(f: impl FnOnce() -> T + Send) -> Option<T> {
    // Evaluation recurses with the user's functions (up to `max_recursion_depth`) and expression
    // nesting; a dedicated thread with a large stack keeps that independent of the caller's
    // thread (test harness and rayon threads have small stacks).
    std::thread::scope(|s| {
        std::thread::Builder::new()
            .name("rtc-eval".into())
            .stack_size(EVAL_STACK_BYTES)
            .spawn_scoped(s, f)
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .ok()
    })
}

/// Stack of the evaluation thread (reserved address space; pages are touched only as needed).
pub(crate) const EVAL_STACK_BYTES: usize = 256 << 20;
