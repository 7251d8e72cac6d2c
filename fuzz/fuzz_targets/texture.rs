//! Image textures. Input: one byte choosing the file extension (which picks the decoder, as
//! for a scene's `image("...")`: png, jpg, hdr, exr), then the file's bytes. The image is
//! decoded by the renderer's texture loader and used as both the colour texture and the bump
//! map of a sphere, rendered 4×4 under each surface mapping.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&kind, bytes)) = data.split_first() else {
        return;
    };
    let ext = ["png", "jpg", "hdr", "exr"][usize::from(kind % 4)];
    let path = rtc_fuzz::scratch().join(format!("t.{ext}"));
    std::fs::write(&path, bytes).expect("write the image");
    rtc_fuzz::texture::exercise(&path);
});
