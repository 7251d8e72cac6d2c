//! `rtc check` geometry findings: CSG on open surfaces, missing or malformed OBJ files (with
//! the OBJ's line), singular transforms, degenerate shapes, all reported in one pass.

mod geometry_support;

use geometry_support::{object, scene};
use glam::{DAffine3, DVec3};
use rtc::diag::Diagnostic;
use rtc::ir::{CsgOp, Object, Shape};
use rtc::opt::{prepare, validate};
use rtc::source::{FileId, Span};

fn at(mut o: Object, start: usize) -> Object {
    o.span = Span::new(FileId(0), start, start + 5);
    o
}

fn ball() -> Object {
    sphere(DVec3::ZERO, 1.0)
}

/// An untransformed sphere.
fn sphere(center: DVec3, radius: f64) -> Object {
    object(Shape::Sphere { center, radius }, DAffine3::IDENTITY)
}

fn csg(children: Vec<Object>) -> Object {
    object(
        Shape::Csg {
            op: CsgOp::Difference,
            children,
        },
        DAffine3::IDENTITY,
    )
}

fn obj_file(name: &str, text: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("rtc-geom-check-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn mesh(path: std::path::PathBuf) -> Object {
    object(
        Shape::Mesh {
            source: rtc::ir::MeshSource::File(path),
            smooth: false,
            use_mtl: false,
        },
        DAffine3::IDENTITY,
    )
}

fn only(diags: &[Diagnostic], code: &str) -> Diagnostic {
    let found: Vec<_> = diags.iter().filter(|d| d.code == code).collect();
    assert_eq!(found.len(), 1, "{code} in {diags:#?}");
    found[0].clone()
}

#[test]
fn csg_on_open_surfaces_is_an_error_at_the_operand() {
    let open_cyl = at(
        object(
            Shape::Cylinder {
                base: DVec3::ZERO,
                top: DVec3::Y,
                radius: 0.5,
                capped: false,
            },
            DAffine3::IDENTITY,
        ),
        10,
    );
    let d = validate(&scene(vec![at(csg(vec![ball(), open_cyl]), 0)])).items;
    let e = only(&d, "rtc::csg::open_operand");
    assert!(e.is_error());
    assert_eq!(
        e.span,
        Some(Span::new(FileId(0), 10, 15)),
        "points at the operand"
    );
    assert_eq!(
        e.labels[0].span,
        Span::new(FileId(0), 0, 5),
        "and at the operation"
    );
    assert_eq!(e.help.as_deref(), Some("set `capped: true`"));

    let tri = at(
        object(
            Shape::Triangle {
                vertices: [DVec3::ZERO, DVec3::X, DVec3::Y],
            },
            DAffine3::IDENTITY,
        ),
        20,
    );
    let d = validate(&scene(vec![csg(vec![ball(), tri])])).items;
    let e = only(&d, "rtc::csg::open_operand");
    assert_eq!(
        e.label.as_deref(),
        Some("a triangle is a surface, not a solid")
    );

    // A tetrahedron with one face missing is open too.
    let open = obj_file(
        "open.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n",
    );
    let d = validate(&scene(vec![csg(vec![ball(), at(mesh(open), 30)])])).items;
    let e = only(&d, "rtc::csg::open_operand");
    assert!(
        e.label
            .as_deref()
            .is_some_and(|l| l.contains("is not closed")),
        "{e:?}"
    );
    // ...and the closed one is fine.
    let closed = obj_file(
        "closed.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    );
    assert!(
        validate(&scene(vec![csg(vec![ball(), mesh(closed)])]))
            .items
            .is_empty()
    );
}

#[test]
fn missing_and_malformed_obj_files_are_reported_with_the_line() {
    let missing = at(mesh("/nonexistent/dir/nothing.obj".into()), 40);
    let bad_vertex = obj_file("badv.obj", "# ok\nv 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
    let bad_face = obj_file("badf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 x\n");
    let d = validate(&scene(vec![
        missing,
        at(mesh(bad_vertex), 50),
        at(mesh(bad_face), 60),
    ]))
    .items;
    assert_eq!(d.len(), 3, "{d:#?}");
    let e = only(&d, "rtc::mesh::not_found");
    assert_eq!(e.span, Some(Span::new(FileId(0), 40, 45)));
    assert!(e.message.contains("nothing.obj"));
    let bad: Vec<_> = d
        .iter()
        .filter(|d| d.code == "rtc::mesh::malformed")
        .collect();
    assert_eq!(bad.len(), 2);
    assert!(
        bad[0].message.ends_with("is malformed at line 3"),
        "{}",
        bad[0].message
    );
    assert!(
        bad[1].message.ends_with("is malformed at line 5"),
        "{}",
        bad[1].message
    );
    // Preparing refuses with the errors, never panics.
    let Err(errs) = prepare(&scene(vec![mesh("/nonexistent.obj".into())])) else {
        panic!("a missing mesh cannot be prepared");
    };
    assert_eq!(errs.items[0].code, "rtc::mesh::not_found");
}

#[test]
fn singular_transforms_and_degenerate_shapes_are_errors() {
    let flat = at(
        object(
            Shape::Box {
                min: DVec3::ZERO,
                max: DVec3::ONE,
            },
            DAffine3::from_scale(DVec3::new(1.0, 0.0, 2.0)),
        ),
        70,
    );
    let nested = csg(vec![
        ball(),
        at(
            object(
                Shape::Sphere {
                    center: DVec3::ZERO,
                    radius: 1.0,
                },
                DAffine3::from_scale(DVec3::new(1e-20, 1.0, 1.0)),
            ),
            80,
        ),
    ]);
    let zero = at(sphere(DVec3::ZERO, 0.0), 90);
    let bent = at(
        object(
            Shape::Polygon {
                points: vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.5), DVec3::Y],
            },
            DAffine3::IDENTITY,
        ),
        100,
    );
    let d = validate(&scene(vec![flat, nested, zero, bent])).items;
    assert_eq!(d.len(), 4, "{d:#?}");
    let sing: Vec<_> = d
        .iter()
        .filter(|d| d.code == "rtc::geometry::singular_transform")
        .collect();
    assert_eq!(sing.len(), 2);
    assert_eq!(sing[0].span, Some(Span::new(FileId(0), 70, 75)));
    assert_eq!(
        sing[1].span,
        Some(Span::new(FileId(0), 80, 85)),
        "found inside the CSG"
    );
    // Shape rules and codes are geometry::shape's, the same the language and course files get.
    assert_eq!(
        only(&d, "rtc::param::out_of_range").span,
        Some(Span::new(FileId(0), 90, 95))
    );
    only(&d, "rtc::param::not_planar");
    // A mirrored (negative) scale is fine.
    let mirrored = object(
        Shape::Box {
            min: DVec3::ZERO,
            max: DVec3::ONE,
        },
        DAffine3::from_scale(DVec3::new(-1.0, 1.0, 1.0)),
    );
    assert!(validate(&scene(vec![mirrored])).items.is_empty());
}

/// `rtc check`'s one pass (`check_owned`: lints, preparation's checks and summary, freeing each
/// object) finds and says what the separate functions do over the same scene.
#[test]
fn owned_check_is_check_and_summary() {
    let zero = at(sphere(DVec3::ZERO, 0.0), 90);
    let flat = at(
        object(
            ball().shape,
            DAffine3::from_scale(DVec3::new(1.0, 0.0, 1.0)),
        ),
        70,
    );
    // The camera (at z = 10) inside an opaque sphere: a lint.
    let around = sphere(DVec3::new(0.0, 0.0, 9.0), 2.0);
    for objects in [
        vec![],
        vec![ball()],
        vec![ball(), zero, flat, around, csg(vec![ball()])],
    ] {
        let sc = scene(objects);
        let (diags, summary) = rtc::check::check_owned(sc.clone());
        assert_eq!(
            format!("{:?}", diags.items),
            format!("{:?}", rtc::check::check(&sc).items)
        );
        assert_eq!(summary, rtc::check::summary(&sc));
    }
}
