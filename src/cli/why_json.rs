//! `rtc why --format json`: the explanation as one JSON document (schema in docs/why.md,
//! pinned by tests/why.rs).

use glam::DVec3;
use serde_json::{Value, json};

use rtc::ir::provenance::StepKind;
use rtc::render::explain::{Explanation, HitInfo, RayNode};

use super::report::place;
use super::why::{Context, material_origin, provenance_text};

/// The whole document.
pub(crate) fn document(cx: &Context<'_>, ex: &Explanation, (w, h): (u32, u32)) -> Value {
    json!({
        "pixel": {"x": ex.x, "y": ex.y},
        "image": {"width": w, "height": h},
        "samples_per_pixel": ex.samples,
        "sample": ex.sample,
        "offset": [ex.offset.0, ex.offset.1],
        "encoding": match ex.encoding {
            rtc::ir::Encoding::Srgb => "srgb",
            rtc::ir::Encoding::Linear => "linear",
        },
        "color": {"linear": v3(ex.color), "bytes": ex.sample_bytes()},
        "pixel_color": {"linear": v3(ex.pixel), "bytes": ex.pixel_bytes()},
        "refined": ex.refined,
        "flare": ex.flare,
        "ray": ray(cx, &ex.root),
    })
}

fn v3(v: DVec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn ray(cx: &Context<'_>, n: &RayNode) -> Value {
    json!({
        "branch": n.branch.name(),
        "k": n.k,
        "rays": n.rays,
        "depth": n.depth,
        "weight": n.weight,
        "origin": v3(n.origin),
        "direction": v3(n.dir),
        "hit": n.hit.as_ref().map(|h| hit(cx, h)),
        "ambient": n.ambient.map(v3),
        "lights": n.lights.iter().map(|l| {
            let t = &l.term;
            json!({
                "index": t.light,
                "span": cx.scene.lights.get(t.light).map(|x| place(cx.sources, x.span)),
                "ambient": v3(t.ambient),
                "diffuse": v3(t.diffuse),
                "specular": v3(t.specular),
                "samples": t.samples,
                "behind": t.behind,
                "blocked": t.blocked,
                "tinted": t.tinted,
                "occluder": l.occluder.as_ref().map(|o| json!({
                    "t": o.t,
                    "point": v3(o.point),
                    "object": object(cx, o.object),
                })),
            })
        }).collect::<Vec<_>>(),
        "local": n.local.map(v3),
        "total_internal_reflection": n.total_internal_reflection,
        "cut": n.cut.iter().map(|(b, k)| json!({"branch": b.name(), "k": k})).collect::<Vec<_>>(),
        "color": v3(n.color),
        "children": n.children.iter().map(|c| ray(cx, c)).collect::<Vec<_>>(),
    })
}

fn hit(cx: &Context<'_>, h: &HitInfo) -> Value {
    let (source, span) = material_origin(cx, h.material);
    json!({
        "t": h.t,
        "point": v3(h.point),
        "normal": v3(h.normal),
        "object": object(cx, h.object),
        "material": {
            "index": h.material.0,
            "source": source,
            "span": span.map(|s| place(cx.sources, s)),
        },
        "patterns": h.patterns.iter().map(|r| json!({
            "role": r.role,
            "name": r.name,
            "value": r.value,
            "stop": r.stop.map(|(i, at, n)| json!({"index": i, "at": at, "of": n})),
        })).collect::<Vec<_>>(),
    })
}

/// An object: index, kind, span and the loops and calls that made it.
fn object(cx: &Context<'_>, i: u32) -> Value {
    let o = cx.scene.objects.get(i as usize);
    let chains: Vec<Value> = cx
        .provenance
        .map(|p| p.trace(i as usize))
        .unwrap_or_default()
        .iter()
        .map(|chain| {
            Value::Array(
                chain
                    .iter()
                    .map(|s| match &s.kind {
                        StepKind::Iteration { at, bindings } => json!({
                            "kind": "iteration",
                            "bindings": bindings,
                            "span": place(cx.sources, *at),
                        }),
                        StepKind::Call { name, at } => json!({
                            "kind": "call",
                            "name": name,
                            "span": place(cx.sources, *at),
                        }),
                    })
                    .collect(),
            )
        })
        .collect();
    json!({
        "index": i,
        "kind": o.map(|o| o.shape.kind_name()),
        "span": o.map(|o| place(cx.sources, o.span)),
        "trace": chains,
        "trace_text": provenance_text(cx, i),
    })
}
