//! `rtc why SCENE X Y`: what made one pixel. The scene is evaluated with provenance on, the
//! pixel's sample is traced with a recorder ([`rtc::render::explain`]), and every hit is shown
//! as a note at the object's source with the loops and calls that made it, its material, each
//! light's terms and occluder, and the reflected and refracted rays below it (docs/why.md).
//! `--format json` prints the same as one document ([`super::why_json`]).

use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::PathBuf;

use rtc::diag::{Diagnostic, Severity, TraceFrame};
use rtc::ir::provenance::{Step, StepKind};
use rtc::ir::{Provenance, Scene};
use rtc::render::explain::{Explanation, HitInfo, RayNode};
use rtc::render::record::Branch;
use rtc::source::{SourceMap, Span};

use crate::cli::inputs::SceneInputs;
use crate::cli::report::{self, Format, location};
use crate::cli::{Outcome, outcome_of, usage_error};

/// `rtc why`'s arguments.
#[derive(clap::Args, Debug)]
pub(crate) struct WhyArgs {
    /// The scene file (`.rtc`, `.in` or `.yaml`).
    file: PathBuf,
    /// The pixel's column (0 = left).
    #[arg(allow_negative_numbers = true)]
    x: i64,
    /// The pixel's row (0 = top).
    #[arg(allow_negative_numbers = true)]
    y: i64,
    /// Explain sample K of the pixel's first grid instead of the pixel centre.
    #[arg(long, value_name = "K")]
    sample: Option<u32>,
    /// `human` (source snippets), `short` (one line per location) or `json`.
    #[arg(long, value_enum, default_value = "human")]
    format: Format,
    #[command(flatten)]
    inputs: SceneInputs,
}

/// What the formatters read besides the explanation.
pub(crate) struct Context<'a> {
    /// Every file read.
    pub(crate) sources: &'a SourceMap,
    /// The evaluated scene (object, material and light spans).
    pub(crate) scene: &'a Scene,
    /// Where objects came from (`.rtc` scenes).
    pub(crate) provenance: Option<&'a Provenance>,
}

/// Runs `rtc why`.
pub(crate) fn run(a: &WhyArgs) -> Outcome {
    let mut opts = match a.inputs.options(a.inputs.frame) {
        Ok(o) => o,
        Err(msg) => return usage_error(&msg),
    };
    opts.provenance = true;
    let subject = a.file.display().to_string();
    let color = a.format == Format::Human && std::io::stderr().is_terminal();
    let mut sources = SourceMap::new();
    let loaded = rtc::loader::load(&a.file, &mut sources, &opts);
    let print = |diags: &[Diagnostic], sources: &SourceMap| {
        let text = report::render(diags, sources, &subject, a.format, color);
        if !text.is_empty() {
            eprintln!("{}", text.trim_end());
        }
    };
    let Some(scene) = &loaded.scene else {
        print(&loaded.diagnostics.items, &sources);
        return outcome_of(&loaded.diagnostics, false);
    };
    let prepared = match rtc::opt::prepare(scene) {
        Ok(p) => p,
        Err(d) => {
            print(&d.items, &sources);
            return outcome_of(&d, false);
        }
    };
    let (w, h) = (scene.camera.width, scene.camera.height);
    let (Ok(x), Ok(y)) = (u32::try_from(a.x), u32::try_from(a.y)) else {
        print(&[outside(a.x, a.y, w, h, scene.camera.span)], &sources);
        return Outcome::SceneErrors;
    };
    if x >= w || y >= h {
        print(&[outside(a.x, a.y, w, h, scene.camera.span)], &sources);
        return Outcome::SceneErrors;
    }
    let ex = match rtc::render::explain::explain(&prepared, x, y, a.sample) {
        Ok(ex) => ex,
        Err(d) => {
            print(&[d], &sources);
            return Outcome::SceneErrors;
        }
    };
    let cx = Context {
        sources: &sources,
        scene,
        provenance: loaded.provenance.as_ref(),
    };
    match a.format {
        Format::Json => println!("{}", super::why_json::document(&cx, &ex, (w, h))),
        Format::Human | Format::Short => {
            let color = std::io::stdout().is_terminal();
            print!("{}", text(&cx, &ex, (w, h), a.format, color));
        }
    }
    Outcome::Ok
}

/// The diagnostic for a pixel outside the image.
fn outside(x: i64, y: i64, w: u32, h: u32, camera: Span) -> Diagnostic {
    Diagnostic::error(
        "rtc::why::pixel",
        camera,
        format!("pixel ({x}, {y}) is outside the {w}×{h} image"),
    )
    .with_label(format!("this camera makes a {w}×{h} image"))
    .with_help(format!(
        "give a column from 0 to {} (left to right) and a row from 0 to {} (top to bottom)",
        w.saturating_sub(1),
        h.saturating_sub(1)
    ))
}

/// A vector as text: four decimals per component.
fn vec3(v: glam::DVec3) -> String {
    format!("[{:.4}, {:.4}, {:.4}]", v.x, v.y, v.z)
}

/// The rays of a tree in the order they are numbered: a ray, then its children's subtrees.
fn numbered(root: &RayNode) -> Vec<&RayNode> {
    fn walk<'a>(n: &'a RayNode, out: &mut Vec<&'a RayNode>) {
        out.push(n);
        for c in &n.children {
            walk(c, out);
        }
    }
    let mut out = Vec::new();
    walk(root, &mut out);
    out
}

/// The one-line provenance of a chain (innermost first), e.g. "iteration i = 3 of the `for`
/// at city.rtc:12, called from `tower()` at city.rtc:30".
fn chain_text(sources: &SourceMap, chain: &[&Step]) -> String {
    let at = |s: Span| {
        let f = sources.get(s.file);
        format!("{}:{}", f.path.display(), f.line_col(s.start as usize).0)
    };
    chain
        .iter()
        .enumerate()
        .map(|(i, s)| match (&s.kind, i) {
            (StepKind::Iteration { at: a, bindings }, 0) => {
                format!("iteration {bindings} of the `for` at {}", at(*a))
            }
            (StepKind::Iteration { at: a, bindings }, _) => {
                format!("in iteration {bindings} of the `for` at {}", at(*a))
            }
            // Read after "made in" or "placed by a group in": no second "in".
            (StepKind::Call { name, at: a }, 0) => format!("`{name}()` called at {}", at(*a)),
            (StepKind::Call { name, at: a }, _) => format!("called from `{name}()` at {}", at(*a)),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// An object's provenance as text: its chains joined ("made …; placed …"), or `None` for an
/// object made at the top level.
pub(crate) fn provenance_text(cx: &Context<'_>, object: u32) -> Option<String> {
    let chains = cx.provenance?.trace(object as usize);
    let parts: Vec<String> = chains
        .iter()
        .filter(|c| !c.is_empty())
        .map(|c| chain_text(cx.sources, c))
        .collect();
    (!parts.is_empty()).then(|| parts.join("; placed by a group in "))
}

/// What a material id is: the scene's material (with its span), the default one, or a mesh's.
pub(crate) fn material_origin(
    cx: &Context<'_>,
    id: rtc::ir::MaterialId,
) -> (&'static str, Option<Span>) {
    let i = id.0 as usize;
    if i < cx.scene.materials.len() {
        ("scene", Some(cx.scene.materials[i].span))
    } else if i == cx.scene.materials.len() {
        ("default", None)
    } else {
        ("mtl", None)
    }
}

/// The name of an object for text: `sphere #3`.
fn object_name(scene: &Scene, object: u32) -> String {
    let kind = scene
        .objects
        .get(object as usize)
        .map_or("object", |o| o.shape.kind_name());
    format!("{kind} #{object}")
}

fn branch_text(n: &RayNode) -> String {
    match n.branch {
        Branch::Camera => "camera ray".to_string(),
        b if n.rays > 1 => format!(
            "{} ray (1 of {} glossy rays weighing {} together)",
            b.name(),
            n.rays,
            rtc::diag::number(n.k)
        ),
        b => format!("{} ray ×{}", b.name(), rtc::diag::number(n.k)),
    }
}

/// The whole human or short text.
fn text(
    cx: &Context<'_>,
    ex: &Explanation,
    (w, h): (u32, u32),
    format: Format,
    color: bool,
) -> String {
    let mut out = String::new();
    let which = match ex.sample {
        None => "the pixel centre".to_string(),
        Some(k) => format!("sample {k}"),
    };
    let _ = writeln!(
        out,
        "pixel ({}, {}) of the {w}×{h} image, {} sample(s) per pixel: explaining {which} (offset {}, {})",
        ex.x,
        ex.y,
        ex.samples,
        rtc::diag::number(ex.offset.0),
        rtc::diag::number(ex.offset.1)
    );
    let enc = match ex.encoding {
        rtc::ir::Encoding::Srgb => "sRGB",
        rtc::ir::Encoding::Linear => "linear",
    };
    let _ = writeln!(
        out,
        "colour of the explained ray: linear {} → bytes {:?} ({enc})",
        vec3(ex.color),
        ex.sample_bytes()
    );
    let same = if ex.pixel == ex.color {
        " (the same)"
    } else {
        ""
    };
    let refined = if ex.refined {
        ", refined by adaptive sampling"
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "the rendered pixel: linear {} → bytes {:?}{same}{refined}",
        vec3(ex.pixel),
        ex.pixel_bytes()
    );
    if ex.flare {
        let _ = writeln!(out, "note: the image adds a lens flare after this value");
    }
    let rays = numbered(&ex.root);
    for (i, n) in rays.iter().enumerate() {
        out.push('\n');
        let indent = "  ".repeat(n.depth as usize);
        let _ = writeln!(
            out,
            "{indent}ray {i}: {} (depth {}, weight {}) from {} along {}",
            branch_text(n),
            n.depth,
            rtc::diag::number(n.weight),
            vec3(n.origin),
            vec3(n.dir)
        );
        match &n.hit {
            None => {
                let _ = writeln!(
                    out,
                    "{indent}  misses everything: background {}",
                    vec3(n.color)
                );
            }
            Some(hit) => {
                let mut d = hit_note(cx, i, n, hit, &rays);
                // The facts read best as plain lines under the snippet than as miette's help.
                let notes = std::mem::take(&mut d.notes);
                let shown = report::render(&[d], cx.sources, "", format, color);
                for line in shown.trim_end().lines() {
                    let _ = writeln!(out, "{}", format!("{indent}  {line}").trim_end());
                }
                for note in notes {
                    let _ = writeln!(out, "{indent}  - {note}");
                }
            }
        }
    }
    out
}

/// The note shown for a ray's hit: at the object's span, with its material, occluders and
/// provenance as labels and trace, and the shading as notes.
fn hit_note(
    cx: &Context<'_>,
    i: usize,
    n: &RayNode,
    hit: &HitInfo,
    rays: &[&RayNode],
) -> Diagnostic {
    let name = object_name(cx.scene, hit.object);
    let span = cx.scene.objects.get(hit.object as usize).map(|o| o.span);
    let mut d = Diagnostic::new(
        Severity::Note,
        "rtc::why::hit",
        span,
        format!("ray {i} hits {name} at t = {}", rtc::diag::number(hit.t)),
    )
    .with_label(format!("{name}, made here"));
    if let Some(p) = provenance_text(cx, hit.object) {
        d = d.with_note(format!("made in {p}"));
    }
    d = d.with_note(format!(
        "point {}, normal {}",
        vec3(hit.point),
        vec3(hit.normal)
    ));
    match material_origin(cx, hit.material) {
        ("scene", Some(ms)) => {
            d = d.with_secondary(ms, "its material");
            d = d.with_note(format!(
                "material #{} defined at {}",
                hit.material.0,
                location(cx.sources, ms)
            ));
        }
        ("default", _) => d = d.with_note("material: the default (the object names none)"),
        _ => {
            d = d.with_note(format!(
                "material #{}: from the mesh's MTL file",
                hit.material.0
            ))
        }
    }
    for r in &hit.patterns {
        let stop = r.stop.map_or(String::new(), |(i, at, n)| {
            format!(
                ", in the colour map's stop {} of {n} (at {})",
                i + 1,
                rtc::diag::number(at)
            )
        });
        d = d.with_note(format!(
            "{} pattern `{}` = {}{stop}",
            r.role,
            r.name,
            rtc::diag::number(r.value)
        ));
    }
    if let Some(a) = n.ambient {
        d = d.with_note(format!("ambient (once): {}", vec3(a)));
    }
    for l in &n.lights {
        let t = &l.term;
        let at = cx
            .scene
            .lights
            .get(t.light)
            .map(|x| format!(" at {}", location(cx.sources, x.span)))
            .unwrap_or_default();
        let mut s = format!(
            "light {}{at}: ambient {} + diffuse {} + specular {}",
            t.light,
            vec3(t.ambient),
            vec3(t.diffuse),
            vec3(t.specular)
        );
        if t.behind > 0 {
            let _ = write!(
                s,
                "; behind the surface for {} of {} sample(s)",
                t.behind, t.samples
            );
        }
        if t.tinted > 0 {
            let _ = write!(
                s,
                "; through glass for {} of {} sample(s)",
                t.tinted, t.samples
            );
        }
        if t.blocked > 0 {
            let _ = write!(s, "; shadowed for {} of {} sample(s)", t.blocked, t.samples);
            if let Some(o) = &l.occluder {
                let oname = object_name(cx.scene, o.object);
                let _ = write!(s, " by {oname}");
                if let Some(os) = cx.scene.objects.get(o.object as usize).map(|x| x.span) {
                    let _ = write!(s, " at {}", location(cx.sources, os));
                    d = d.with_secondary(os, format!("{oname} shadows light {}", t.light));
                }
            }
        }
        d = d.with_note(s);
    }
    if let Some(c) = n.local {
        d = d.with_note(format!("local colour (the shading model): {}", vec3(c)));
    }
    if n.total_internal_reflection {
        d = d.with_note("total internal reflection: the refracted share goes to the reflected ray");
    }
    for (b, k) in &n.cut {
        d = d.with_note(format!(
            "{} ray ×{} not traced: its weight is under the cut-off",
            b.name(),
            rtc::diag::number(*k)
        ));
    }
    for c in &n.children {
        let j = rays.iter().position(|r| std::ptr::eq(*r, c)).unwrap_or(0);
        d = d.with_note(format!(
            "{} → ray {j}, colour {}",
            branch_text(c),
            vec3(c.color)
        ));
    }
    d = d.with_note(format!("colour of ray {i}: {}", vec3(n.color)));
    if let Some(p) = cx.provenance {
        for chain in p.trace(hit.object as usize) {
            for s in chain {
                d.trace.push(match &s.kind {
                    StepKind::Iteration { at, bindings } => TraceFrame {
                        span: *at,
                        message: format!("in iteration {bindings} of this `for`"),
                    },
                    StepKind::Call { name, at } => TraceFrame {
                        span: *at,
                        message: format!("in call of `{name}`"),
                    },
                });
            }
        }
    }
    d
}
