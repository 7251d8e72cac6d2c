// Throwaway study probe (not committed): the exact adaptive-refinement mask of a scene, from the
// film of its 1x1 (min = 1) render, with the renderer's criterion (a 4-neighbour differs by more
// than the threshold in some channel). Usage: refine_probe SCENE_U1.rtc THRESHOLD OUT_MASK.png
use std::path::Path;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let mut sources = rtc::source::SourceMap::default();
    let loaded = rtc::frontend::load(Path::new(&a[1]), &mut sources, &rtc::eval::EvalOptions::default());
    let scene = loaded.scene.expect("scene");
    let t: f64 = a[2].parse().unwrap();
    let film = rtc::render::render_film(&scene, &rtc::render::RenderOptions::default()).unwrap();
    let (w, h) = (film.width, film.height);
    let mut mask = image::GrayImage::new(w, h);
    let mut n = 0;
    for y in 0..h { for x in 0..w {
        let c = film.get(x, y);
        let d = |nx: u32, ny: u32| (film.get(nx, ny) - c).abs().max_element() > t;
        let e = (x > 0 && d(x - 1, y)) || (x + 1 < w && d(x + 1, y)) || (y > 0 && d(x, y - 1)) || (y + 1 < h && d(x, y + 1));
        if e { n += 1; mask.put_pixel(x, y, image::Luma([255])); }
    }}
    mask.save(&a[3]).unwrap();
    println!("{n}");
}
