//! Span erasure, so scenes from different files (`rt1.in` and `scene01.yaml`) compare equal when
//! they describe the same thing.

use crate::ir::{Object, Scene, Shape, Texture};
use crate::source::Span;

/// A copy of `scene` with every span set to the default, for equality "apart from spans".
pub fn erase_spans(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    s.camera.span = Span::default();
    for l in &mut s.lights {
        l.span = Span::default();
    }
    for m in &mut s.materials {
        m.span = Span::default();
    }
    for t in &mut s.textures {
        if let Texture::Image { span, .. } = t {
            *span = Span::default();
        }
    }
    for o in &mut s.objects {
        erase_object(o);
    }
    s
}

fn erase_object(o: &mut Object) {
    o.span = Span::default();
    if let Shape::Csg { children, .. } = &mut o.shape {
        for c in children {
            erase_object(c);
        }
    }
}
