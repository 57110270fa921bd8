//! The `m3g-render` command-line tool run as a user would: frame sequences with an animated
//! PNG, camera selection, argument and file errors (exit code 2), and every corpus file.
//! The corpus tests are skipped (with a note) when `tests/data/m3g` is missing.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use image::AnimationDecoder;

const EXE: &str = env!("CARGO_BIN_EXE_m3g-render");

#[path = "common/corpus.rs"]
mod corpus;

fn corpus_dir() -> Option<PathBuf> {
    corpus::m3g_corpus()
}

/// A fresh temporary folder for one test.
fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("m3g-render-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    Command::new(EXE)
        .args(args.iter().map(|a| a.as_ref()))
        .output()
        .unwrap()
}

fn rgb(path: &Path) -> image::RgbImage {
    image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8()
}

#[test]
fn frames_write_numbered_pngs_and_an_animated_png() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("frames");
    let out = dir.join("robot.png");
    let o = run(&[
        &corpus.join("robot.m3g"),
        &"--frames",
        &"3",
        &"--step",
        &"500",
        &"--size",
        &"120x160",
        &"--out",
        &out,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let frames: Vec<image::RgbImage> = (0..3)
        .map(|i| rgb(&dir.join(format!("robot-{i:03}.png"))))
        .collect();
    for f in &frames {
        assert_eq!(f.dimensions(), (120, 160));
    }
    // robot.m3g is animated: the three times give three different pictures.
    assert_ne!(frames[0], frames[1]);
    assert_ne!(frames[1], frames[2]);
    assert_ne!(frames[0], frames[2]);
    // A frame equals the single render at its time.
    let single = dir.join("t500.png");
    let o = run(&[
        &corpus.join("robot.m3g"),
        &"--time",
        &"500",
        &"--size",
        &"120x160",
        &"--out",
        &single,
    ]);
    assert!(o.status.success());
    assert_eq!(rgb(&single), frames[1]);
    // The animated PNG decodes (with the image crate's APNG reader) to the same frames,
    // each shown for the step.
    let dec = image::codecs::png::PngDecoder::new(std::io::BufReader::new(
        std::fs::File::open(&out).unwrap(),
    ))
    .unwrap();
    assert!(dec.is_apng().unwrap());
    let anim: Vec<image::Frame> = dec
        .apng()
        .unwrap()
        .into_frames()
        .map(|f| f.unwrap())
        .collect();
    assert_eq!(anim.len(), 3);
    for (a, f) in anim.iter().zip(&frames) {
        assert_eq!(a.delay().numer_denom_ms(), (500, 1));
        assert_eq!(&image::DynamicImage::from(a.buffer().clone()).to_rgb8(), f);
    }
    // Non-APNG readers see the first frame.
    assert_eq!(rgb(&out), frames[0]);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn camera_selection() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("camera");
    let file = corpus.join("robot.m3g");
    // A missing user ID fails with code 2 and names the cameras there are.
    let o = run(&[&file, &"--camera", &"987654", &"--out", &dir.join("x.png")]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.starts_with("m3g-render: "), "{err}");
    assert!(err.contains("no Camera with user ID 987654"), "{err}");
    assert!(!dir.join("x.png").exists());
    // A non-number is an argument error.
    let o = run(&[&file, &"--camera", &"main"]);
    assert_eq!(o.status.code(), Some(2));
    // The active camera's own user ID renders the same image as no --camera.
    let loaded = GLES_CM::m3g::Loader::new().load_file(&file).unwrap();
    let world = loaded
        .roots
        .iter()
        .find_map(|r| r.downcast::<GLES_CM::m3g::World>())
        .unwrap();
    use GLES_CM::m3g::Object3DExt;
    let cam_id = world.active_camera().unwrap().user_id();
    let (a, b) = (dir.join("a.png"), dir.join("b.png"));
    assert!(run(&[&file, &"--out", &a]).status.success());
    let o = run(&[&file, &"--camera", &cam_id.to_string(), &"--out", &b]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(rgb(&a), rgb(&b));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_and_files_exit_2() {
    let dir = tmp("bad");
    let junk = dir.join("junk.m3g");
    std::fs::write(&junk, b"not an m3g file at all").unwrap();
    let cases: Vec<Vec<String>> = vec![
        vec![],
        vec!["x.m3g".into(), "--frames".into()],
        vec!["x.m3g".into(), "--frames".into(), "0".into()],
        vec!["x.m3g".into(), "--frames".into(), "two".into()],
        vec!["x.m3g".into(), "--step".into(), "10".into()],
        vec!["x.m3g".into(), "--size".into(), "10".into()],
        vec!["x.m3g".into(), "--bogus".into()],
        vec!["a.m3g".into(), "b.m3g".into()],
        vec![
            "x.m3g".into(),
            "--time".into(),
            "2147483000".into(),
            "--frames".into(),
            "10".into(),
            "--step".into(),
            "1000".into(),
        ],
        vec![dir.join("missing.m3g").display().to_string()],
        vec![junk.display().to_string()],
    ];
    for args in cases {
        let o = Command::new(EXE).args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("m3g-render: "), "{args:?}: {err}");
        // Argument errors add the usage line; file errors are one line.
        let file_error = args.iter().any(|a| a.starts_with(dir.to_str().unwrap()));
        assert_eq!(err.contains("usage:"), !file_error, "{args:?}: {err}");
    }
    let o = run(&[&"--help"]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stdout).contains("--camera"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn every_corpus_file_renders() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("corpus");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&corpus)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "m3g"))
        .collect();
    files.sort();
    assert!(!files.is_empty());
    for f in files {
        let out = dir.join(f.file_name().unwrap()).with_extension("png");
        let o = run(&[&f, &"--time", &"1000", &"--out", &out]);
        assert!(
            o.status.success(),
            "{}: {}",
            f.display(),
            String::from_utf8_lossy(&o.stderr)
        );
        assert_eq!(rgb(&out).dimensions(), (240, 320));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A World whose Background shows a 2 × 1 image of `format` (red, then green, as phone
/// content made for an RGB `Graphics` target has it), written as a `.m3g` file.
fn background_world_file(dir: &Path, format: i32) -> PathBuf {
    use GLES_CM::m3g::{Background, Camera, GroupExt, Image2D, Object3DExt, World};
    let bpp = if format == Image2D::RGBA { 4 } else { 3 };
    let mut pixels = vec![0u8; 2 * bpp];
    pixels[0] = 255; // red
    pixels[bpp + 1] = 255; // green
    if bpp == 4 {
        pixels[3] = 255;
        pixels[7] = 255;
    }
    let image = Image2D::with_pixels(format, 2, 1, &pixels).unwrap();
    let bg = Background::new();
    bg.set_image(Some(&image)).unwrap();
    bg.set_crop(0, 0, 2, 1).unwrap();
    let world = World::new();
    let camera = Camera::new();
    world.add_child(&camera).unwrap();
    world.set_active_camera(&camera);
    world.set_background(Some(&bg));
    let bytes = GLES_CM::m3g::writer::save(&[world.as_object3d()], false).unwrap();
    let path = dir.join(format!("background-{format}.m3g"));
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn rgb_backgrounds_render_on_the_default_graphics_target() {
    let dir = tmp("rgb-background");
    let rgb_file = background_world_file(&dir, GLES_CM::m3g::Image2D::RGB);
    let out = dir.join("rgb.png");
    let o = run(&[&rgb_file, &"--size", &"4x2", &"--out", &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = rgb(&out);
    // The 2 × 1 image stretched over 4 × 2 pixels: red on the left, green on the right.
    assert_eq!(img.get_pixel(0, 0).0, [255, 0, 0]);
    assert_eq!(img.get_pixel(3, 1).0, [0, 255, 0]);

    // An RGBA Image2D target wants RGBA backgrounds: the error names both formats.
    let o = run(&[&rgb_file, &"--target", &"rgba", &"--out", &out]);
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("background image format RGB differs from the target's RGBA"),
        "{err}"
    );
    let rgba_file = background_world_file(&dir, GLES_CM::m3g::Image2D::RGBA);
    let o = run(&[
        &rgba_file,
        &"--target",
        &"rgba",
        &"--size",
        &"4x2",
        &"--out",
        &out,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(rgb(&out).get_pixel(0, 0).0, [255, 0, 0]);
    let o = run(&[&rgba_file, &"--out", &out]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("background image format RGBA differs from the target's RGB"),
        "{err}"
    );
    let o = run(&[&rgba_file, &"--target", &"bgr"]);
    assert_eq!(o.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).ok();
}
