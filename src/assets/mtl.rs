//! MTL materials (read by tobj with the OBJ file) as rtc materials.

use glam::DVec3;

use crate::ir::Material;

/// The image an MTL material's `map_Kd` names, resolved in `dir` (its options, such as
/// `-s 1 1 1`, before the file name are not read: the file name is the last word).
pub(crate) fn image(m: &tobj::Material, dir: &std::path::Path) -> Option<std::path::PathBuf> {
    let name = m.diffuse_texture.as_deref()?.split_whitespace().last()?;
    Some(dir.join(name))
}

/// Converts an MTL material (Kd colour, Ka/Ks scaled to rtc's scalar coefficients, Ns, d, Ni).
pub(crate) fn convert(m: &tobj::Material) -> Material {
    let v = |c: [f32; 3]| DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64);
    let mut out = Material::default();
    if let Some(kd) = m.diffuse {
        out.color = v(kd);
        out.kd = 1.0;
    }
    if let Some(ka) = m.ambient {
        let ka = v(ka).max_element();
        out.ka = ka;
    }
    if let Some(ks) = m.specular {
        out.ks = v(ks).max_element();
    }
    if let Some(ns) = m.shininess {
        out.n = (ns as f64).max(1.0);
    }
    if let Some(d) = m.dissolve
        && d < 1.0
    {
        out.refract = (1.0 - d as f64).clamp(0.0, 1.0);
    }
    if let Some(ni) = m.optical_density {
        out.eta = (ni as f64).max(1.0);
    }
    out
}
