//! The `m3g` command-line tool run as a user would: frame sequences with an animated PNG,
//! camera selection, argument and file errors (exit code 2), every corpus file; a folder in
//! one run with `--out-dir` and a bad file among good ones; `info` as text and JSON; files
//! without a World; `--animate` over the whole animation; GIF output; `--version`.
//! The corpus tests are skipped (with a note) when `tests/data/m3g` is missing.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use image::AnimationDecoder;
use m3g::Object3DExt;

const EXE: &str = env!("CARGO_BIN_EXE_m3g");

#[path = "../../m3g/tests/common/corpus.rs"]
mod corpus;
#[path = "../../m3g/tests/common/deep.rs"]
mod deep;
#[path = "../../m3g/tests/common/m3g_file.rs"]
mod m3g_file;

fn corpus_dir() -> Option<PathBuf> {
    corpus::m3g_corpus()
}

/// A fresh temporary folder for one test.
fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("m3g-cli-{}-{name}", std::process::id()));
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
    assert!(err.starts_with("m3g: "), "{err}");
    assert!(err.contains("no Camera with user ID 987654"), "{err}");
    assert!(!dir.join("x.png").exists());
    // A non-number is an argument error.
    let o = run(&[&file, &"--camera", &"main"]);
    assert_eq!(o.status.code(), Some(2));
    // The active camera's own user ID renders the same image as no --camera.
    let loaded = m3g::Loader::new().load_file(&file).unwrap();
    let world = loaded
        .roots
        .iter()
        .find_map(|r| r.downcast::<m3g::World>())
        .unwrap();
    use m3g::Object3DExt;
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
    // A well-formed file cut short inside its last section.
    let whole = m3g_file::file(false, &[(0, vec![m3g_file::mutable_image(4)])]);
    let cut = dir.join("cut.m3g");
    std::fs::write(&cut, &whole[..whole.len() - 10]).unwrap();
    let cases: Vec<Vec<String>> = vec![
        vec![],
        vec!["x.m3g".into(), "--frames".into()],
        vec!["x.m3g".into(), "--frames".into(), "0".into()],
        vec!["x.m3g".into(), "--frames".into(), "two".into()],
        vec!["x.m3g".into(), "--step".into(), "10".into()],
        vec!["x.m3g".into(), "--size".into(), "10".into()],
        vec!["x.m3g".into(), "--size".into(), "0x5".into()],
        vec!["x.m3g".into(), "--time".into(), "soon".into()],
        vec!["x.m3g".into(), "--bogus".into()],
        vec![
            "a.m3g".into(),
            "b.m3g".into(),
            "--out".into(),
            "x.png".into(),
        ],
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
        vec![cut.display().to_string()],
    ];
    for args in cases {
        let o = Command::new(EXE).args(&args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("m3g: "), "{args:?}: {err}");
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
fn background_world_file(dir: &Path, format: m3g::ImageFormat) -> PathBuf {
    use m3g::{Background, Camera, GroupExt, Image2D, ImageFormat, Object3DExt, World};
    let bpp = if format == ImageFormat::Rgba { 4 } else { 3 };
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
    let bytes = m3g::writer::save(&[world.as_object3d()], false).unwrap();
    let path = dir.join(format!("background-{}.m3g", format.as_raw()));
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn rgb_backgrounds_render_on_the_default_graphics_target() {
    let dir = tmp("rgb-background");
    let rgb_file = background_world_file(&dir, m3g::ImageFormat::Rgb);
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
    let rgba_file = background_world_file(&dir, m3g::ImageFormat::Rgba);
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

// ---------------------------------------------------------------------------------------
// Several files, info, files without a World, --animate, GIF, --version.

/// The `.m3g` files of the corpus, in name order.
fn corpus_files(corpus: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(corpus)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "m3g"))
        .collect();
    files.sort();
    files
}

/// How many different colors `img` has (1 for a blank image).
fn colors(img: &image::RgbImage) -> usize {
    let mut c: Vec<[u8; 3]> = img.pixels().map(|p| p.0).collect();
    c.sort_unstable();
    c.dedup();
    c.len()
}

#[test]
fn a_folder_renders_in_one_run_into_out_dir() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("out-dir");
    let out = dir.join("images"); // created by the tool
    let o = run(&[&corpus, &"--size", &"96x128", &"--out-dir", &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    let files = corpus_files(&corpus);
    assert!(files.len() >= 10);
    for f in &files {
        let png = out.join(f.file_stem().unwrap()).with_extension("png");
        assert!(stdout.contains(&png.display().to_string()), "{stdout}");
        let img = rgb(&png);
        assert_eq!(img.dimensions(), (96, 128), "{}", png.display());
        assert!(colors(&img) > 1, "{} is blank", png.display());
    }
    // Nothing else was written.
    assert_eq!(std::fs::read_dir(&out).unwrap().count(), files.len());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_bad_file_among_good_ones_fails_alone_with_exit_2() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("bad-among-good");
    let input = dir.join("in");
    std::fs::create_dir_all(&input).unwrap();
    for name in ["simple.m3g", "cube.m3g"] {
        std::fs::copy(corpus.join(name), input.join(name)).unwrap();
    }
    // Sorted between the good ones, so the run goes on after it.
    std::fs::write(input.join("junk.m3g"), b"not an m3g file at all").unwrap();
    let out = dir.join("out");
    let o = run(&[&input, &"--size", &"32x32", &"--out-dir", &out]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    let junk = input.join("junk.m3g").display().to_string();
    assert!(err.contains(&format!("m3g: {junk}: ")), "{err}");
    assert!(
        err.contains(&format!("1 of 3 files failed: {junk}")),
        "{err}"
    );
    assert!(!err.contains("usage:"), "{err}");
    assert_eq!(rgb(&out.join("cube.png")).dimensions(), (32, 32));
    assert_eq!(rgb(&out.join("simple.png")).dimensions(), (32, 32));
    assert!(!out.join("junk.png").exists());
    // Files named one by one: a missing one fails the same way.
    let missing = dir.join("missing.m3g");
    let o = run(&[
        &input.join("cube.m3g"),
        &missing,
        &"--out-dir",
        &dir.join("two"),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("1 of 2 files failed"), "{err}");
    assert!(dir.join("two/cube.png").is_file());
    // Two inputs that would write the same output: the second is refused.
    let o = run(&[
        &input.join("cube.m3g"),
        &input.join("cube.m3g"),
        &"--out-dir",
        &out,
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("is that of"));
    // --out names one output only.
    let o = run(&[&input, &"--out", &dir.join("x.png")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("usage:"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn info_prints_the_object_tree() {
    let Some(corpus) = corpus_dir() else { return };
    let file = corpus.join("robot.m3g");
    let o = run(&[&"info", &file]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    let loaded = m3g::Loader::new().load_file(&file).unwrap();
    // Every object of the file appears once in full (further times as "(above)").
    for (i, obj) in loaded.objects.iter().enumerate() {
        let head = format!("#{} {} id=", i + 2, obj.class_name());
        let full = text
            .lines()
            .filter(|l| l.trim_start().starts_with(&head))
            .count();
        assert_eq!(full, 1, "{head}\n{text}");
    }
    for want in [
        "World",
        "SkinnedMesh",
        "Camera id=",
        "projection=perspective",
        "Light id=",
        "AnimationTrack",
        "AnimationController",
        "KeyframeSequence",
        "interpolation=",
        "Image2D",
        "Texture2D",
        "wrap_s=",
        "submeshes=",
        "animation: ",
        "  track #",
    ] {
        assert!(text.contains(want), "no {want:?} in\n{text}");
    }
    // Children are indented below their parents.
    assert!(text.lines().any(|l| l.starts_with("    #")), "{text}");
}

/// A JSON value, parsed by the small reader below (the test's own, so that the tool's
/// writer is checked against an independent reading of the grammar).
#[derive(Debug, Clone, PartialEq)]
enum J {
    Null,
    Bool(bool),
    Num(f64),
    Str(String),
    Arr(Vec<J>),
    Obj(Vec<(String, J)>),
}

impl J {
    fn get(&self, key: &str) -> &J {
        match self {
            J::Obj(p) => {
                &p.iter()
                    .find(|(k, _)| k == key)
                    .unwrap_or_else(|| panic!("no {key}"))
                    .1
            }
            _ => panic!("not an object: {self:?}"),
        }
    }
    fn arr(&self) -> &[J] {
        match self {
            J::Arr(a) => a,
            _ => panic!("not an array: {self:?}"),
        }
    }
    fn str(&self) -> &str {
        match self {
            J::Str(s) => s,
            _ => panic!("not a string: {self:?}"),
        }
    }
    fn num(&self) -> f64 {
        match self {
            J::Num(n) => *n,
            _ => panic!("not a number: {self:?}"),
        }
    }
}

fn parse_json(s: &str) -> J {
    struct P<'a>(&'a [u8], usize);
    impl P<'_> {
        fn ws(&mut self) {
            while self.1 < self.0.len() && b" \t\r\n".contains(&self.0[self.1]) {
                self.1 += 1;
            }
        }
        fn eat(&mut self, c: u8) {
            self.ws();
            assert_eq!(self.0.get(self.1), Some(&c), "at byte {}", self.1);
            self.1 += 1;
        }
        fn peek(&mut self) -> u8 {
            self.ws();
            self.0[self.1]
        }
        fn lit(&mut self, w: &str, v: J) -> J {
            assert!(
                self.0[self.1..].starts_with(w.as_bytes()),
                "at byte {}",
                self.1
            );
            self.1 += w.len();
            v
        }
        fn string(&mut self) -> String {
            self.eat(b'"');
            let mut out = Vec::new();
            loop {
                let c = self.0[self.1];
                self.1 += 1;
                match c {
                    b'"' => return String::from_utf8(out).unwrap(),
                    b'\\' => {
                        let e = self.0[self.1];
                        self.1 += 1;
                        let ch = match e {
                            b'"' => '"',
                            b'\\' => '\\',
                            b'/' => '/',
                            b'n' => '\n',
                            b'r' => '\r',
                            b't' => '\t',
                            b'b' => '\u{8}',
                            b'f' => '\u{c}',
                            b'u' => {
                                let h = std::str::from_utf8(&self.0[self.1..self.1 + 4]).unwrap();
                                self.1 += 4;
                                char::from_u32(u32::from_str_radix(h, 16).unwrap()).unwrap()
                            }
                            _ => panic!("bad escape \\{}", e as char),
                        };
                        out.extend_from_slice(ch.to_string().as_bytes());
                    }
                    c if c < 0x20 => panic!("raw control character in a string"),
                    c => out.push(c),
                }
            }
        }
        fn value(&mut self) -> J {
            match self.peek() {
                b'{' => {
                    self.eat(b'{');
                    let mut pairs = Vec::new();
                    if self.peek() == b'}' {
                        self.eat(b'}');
                        return J::Obj(pairs);
                    }
                    loop {
                        let k = self.string();
                        self.eat(b':');
                        pairs.push((k, self.value()));
                        if self.peek() == b',' {
                            self.eat(b',');
                        } else {
                            self.eat(b'}');
                            return J::Obj(pairs);
                        }
                    }
                }
                b'[' => {
                    self.eat(b'[');
                    let mut items = Vec::new();
                    if self.peek() == b']' {
                        self.eat(b']');
                        return J::Arr(items);
                    }
                    loop {
                        items.push(self.value());
                        if self.peek() == b',' {
                            self.eat(b',');
                        } else {
                            self.eat(b']');
                            return J::Arr(items);
                        }
                    }
                }
                b'"' => J::Str(self.string()),
                b't' => self.lit("true", J::Bool(true)),
                b'f' => self.lit("false", J::Bool(false)),
                b'n' => self.lit("null", J::Null),
                _ => {
                    let start = self.1;
                    while self.1 < self.0.len() && b"-+.eE0123456789".contains(&self.0[self.1]) {
                        self.1 += 1;
                    }
                    let t = std::str::from_utf8(&self.0[start..self.1]).unwrap();
                    J::Num(t.parse().unwrap_or_else(|_| panic!("bad number {t:?}")))
                }
            }
        }
    }
    let mut p = P(s.as_bytes(), 0);
    let v = p.value();
    p.ws();
    assert_eq!(p.1, s.len(), "trailing text after the JSON value");
    v
}

#[test]
fn the_test_json_reader_reads_what_it_should() {
    let v = parse_json(r#" {"a": [1, -2.5e1, true, null], "b\n\"": "\u00e9\\"} "#);
    assert_eq!(v.get("a").arr()[1], J::Num(-25.0));
    assert_eq!(v.get("b\n\"").str(), "é\\");
}

#[test]
fn info_json_parses_and_names_the_classes() {
    let Some(corpus) = corpus_dir() else { return };
    let file = corpus.join("robot.m3g");
    let o = run(&[&"info", &"--json", &file]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let doc = parse_json(&String::from_utf8(o.stdout).unwrap());
    assert_eq!(doc.get("file").str(), file.display().to_string());
    assert_eq!(doc.get("header").get("version").str(), "1.0");
    let loaded = m3g::Loader::new().load_file(&file).unwrap();
    let objects = doc.get("objects").arr();
    assert!(objects.len() >= loaded.objects.len());
    for (i, obj) in loaded.objects.iter().enumerate() {
        assert_eq!(objects[i].get("index").num(), (i + 2) as f64);
        assert_eq!(objects[i].get("class").str(), obj.class_name());
    }
    let max = objects.len() as f64 + 1.0;
    for o in objects {
        for r in o.get("references").arr() {
            assert!((2.0..=max).contains(&r.num()), "{r:?}");
        }
    }
    let classes: Vec<&str> = objects.iter().map(|o| o.get("class").str()).collect();
    for want in [
        "World",
        "Camera",
        "Light",
        "SkinnedMesh",
        "Group",
        "VertexBuffer",
        "VertexArray",
        "Appearance",
        "Texture2D",
        "Image2D",
        "KeyframeSequence",
        "AnimationTrack",
        "AnimationController",
    ] {
        assert!(classes.contains(&want), "no {want} in {classes:?}");
    }
    let camera = objects
        .iter()
        .find(|o| o.get("class").str() == "Camera")
        .unwrap();
    assert!(camera.get("params").get("projection").str().len() > 3);
    let tracks = doc.get("animation").get("tracks").arr();
    assert_eq!(
        tracks.len(),
        classes.iter().filter(|c| **c == "AnimationTrack").count()
    );
    assert!(doc.get("animation").get("end").num() > 0.0);
    // Several files: an array, one document per file.
    let o = run(&[&"info", &"--json", &file, &corpus.join("simple.m3g")]);
    assert!(o.status.success());
    let docs = parse_json(&String::from_utf8(o.stdout).unwrap());
    assert_eq!(docs.arr().len(), 2);
    assert!(docs.arr()[1].get("file").str().ends_with("simple.m3g"));
}

/// Writes `roots` as a .m3g file `name` in `dir`.
fn save(dir: &Path, name: &str, roots: &[m3g::Object3D]) -> PathBuf {
    let bytes = m3g::writer::save(roots, false).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// A lit white cube of side 2 around the origin (no camera, no light, no World).
fn cube_mesh() -> m3g::Mesh {
    use m3g::*;
    let mut pos: Vec<i8> = Vec::new();
    let mut nrm: Vec<i8> = Vec::new();
    let mut strips = Vec::new();
    // Each face as a 4-vertex strip: corners of the face at ±1 along the two other axes.
    for axis in 0..3 {
        for sign in [-1i8, 1] {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            let corners = if sign > 0 {
                [(-1, -1), (1, -1), (-1, 1), (1, 1)]
            } else {
                [(-1, -1), (-1, 1), (1, -1), (1, 1)]
            };
            for (a, b) in corners {
                let mut p = [0i8; 3];
                p[axis] = sign;
                p[u] = a;
                p[v] = b;
                pos.extend_from_slice(&p);
                let mut n = [0i8; 3];
                n[axis] = sign * 127;
                nrm.extend_from_slice(&n);
            }
            strips.push(4);
        }
    }
    let positions = VertexArray::new(24, 3, 1).unwrap();
    positions.set_bytes(0, &pos).unwrap();
    let normals = VertexArray::new(24, 3, 1).unwrap();
    normals.set_bytes(0, &nrm).unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&positions), 1.0, None).unwrap();
    vb.set_normals(Some(&normals)).unwrap();
    let ib = TriangleStripArray::new_implicit(0, &strips).unwrap();
    let look = Appearance::new();
    look.set_material(Some(&Material::new()));
    let pm = PolygonMode::new();
    pm.set_culling(Culling::None);
    look.set_polygon_mode(Some(&pm));
    Mesh::new(&vb, &ib.as_index_buffer(), Some(&look))
}

#[test]
fn a_file_without_a_world_renders_under_a_default_camera_and_light() {
    use m3g::*;
    let dir = tmp("no-world");
    // A Group far from the origin, scaled, holding the cube: the framing must use the
    // scale, bias and node transforms to find it.
    let group = Group::new();
    group.set_translation(300.0, -120.0, -900.0);
    group.set_scale(40.0, 40.0, 40.0);
    let cube = cube_mesh();
    cube.set_orientation(30.0, 1.0, 1.0, 0.0).unwrap();
    group.add_child(&cube).unwrap();
    let file = save(&dir, "loose.m3g", &[group.as_object3d()]);
    assert!(Loader::load_path(&file)
        .unwrap()
        .iter()
        .all(|r| r.downcast::<World>().is_none()));
    let out = dir.join("loose.png");
    let o = run(&[&"render", &file, &"--size", &"80x80", &"--out", &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("no World"));
    let img = rgb(&out);
    // Lit (a lit Material without lights would be black) and framed: the middle is the
    // cube, and it fills a good part of the view without touching the border.
    assert_ne!(img.get_pixel(40, 40).0, [0, 0, 0]);
    let lit = img.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    assert!(lit > 80 * 80 / 8, "only {lit} pixels show the cube");
    for i in 0..80 {
        for (x, y) in [(i, 0), (i, 79), (0, i), (79, i)] {
            assert_eq!(img.get_pixel(x, y).0, [0, 0, 0], "({x}, {y})");
        }
    }
    // Shaded: the directional light makes the faces differ.
    assert!(colors(&img) > 2);
    // A file with no node at all has nothing to render.
    let look = save(&dir, "look.m3g", &[Appearance::new().as_object3d()]);
    let o = run(&[&look, &"--out", &dir.join("look.png")]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("nothing to render") && err.contains("Appearance"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A World with a camera and a Group animated by one TRANSLATION track of `duration` ms,
/// repeat `mode`, whose controller has `interval` (if any).
fn animated_world(
    dir: &Path,
    name: &str,
    duration: i32,
    mode: m3g::RepeatMode,
    interval: Option<(i32, i32)>,
) -> PathBuf {
    use m3g::*;
    let world = World::new();
    let camera = Camera::new();
    camera.set_perspective(60.0, 1.0, 0.1, 100.0).unwrap();
    camera.set_translation(0.0, 0.0, 5.0);
    world.add_child(&camera).unwrap();
    world.set_active_camera(&camera);
    world.add_child(&Light::new()).unwrap();
    let group = Group::new();
    group.add_child(&cube_mesh()).unwrap();
    world.add_child(&group).unwrap();
    let seq = KeyframeSequence::new(2, 3, Interpolation::Linear).unwrap();
    seq.set_keyframe(0, 0, &[-1.0, 0.0, 0.0]).unwrap();
    seq.set_keyframe(1, duration / 2, &[1.0, 0.0, 0.0]).unwrap();
    seq.set_duration(duration).unwrap();
    seq.set_repeat_mode(mode);
    let track = AnimationTrack::new(&seq, AnimationProperty::Translation).unwrap();
    let controller = AnimationController::new();
    if let Some((s, e)) = interval {
        controller.set_active_interval(s, e).unwrap();
    }
    track.set_controller(Some(&controller));
    group.add_animation_track(&track).unwrap();
    save(dir, name, &[world.as_object3d()])
}

fn apng_frames(path: &Path) -> Vec<image::Frame> {
    let dec = image::codecs::png::PngDecoder::new(std::io::BufReader::new(
        std::fs::File::open(path).unwrap(),
    ))
    .unwrap();
    dec.apng()
        .unwrap()
        .into_frames()
        .map(|f| f.unwrap())
        .collect()
}

#[test]
fn animate_covers_the_whole_animation() {
    use m3g::RepeatMode;
    let dir = tmp("animate");
    // A loop: one period, its end (= its start) not repeated: 1200 / 100 = 12 frames.
    let looping = animated_world(&dir, "loop.m3g", 1200, RepeatMode::Loop, None);
    let out = dir.join("loop.png");
    let o = run(&[
        &looping,
        &"--animate",
        &"--step",
        &"100",
        &"--size",
        &"32x32",
        &"--out",
        &out,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("loop-011.png").is_file());
    assert!(!dir.join("loop-012.png").exists());
    let frames = apng_frames(&out);
    assert_eq!(frames.len(), 12);
    // The cube moves.
    assert_ne!(frames[0].buffer(), frames[3].buffer());
    // A one-shot sequence: up to and including its end, 2000 / 100 + 1 = 21 frames.
    let once = animated_world(&dir, "once.m3g", 2000, RepeatMode::Constant, None);
    let o = run(&[
        &once,
        &"--animate",
        &"--step",
        &"100",
        &"--size",
        &"32x32",
        &"--format",
        &"apng",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(apng_frames(&dir.join("once.png")).len(), 21);
    assert!(
        !dir.join("once-000.png").exists(),
        "apng writes no frame PNGs"
    );
    // An active interval ends it early: [0, 700) at 100 ms steps is 7 frames (at 700 the
    // track is off and the cube stays where it was).
    let cut = animated_world(&dir, "cut.m3g", 2000, RepeatMode::Constant, Some((0, 700)));
    let o = run(&[
        &cut,
        &"--animate",
        &"--step",
        &"100",
        &"--size",
        &"32x32",
        &"--format",
        &"apng",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(apng_frames(&dir.join("cut.png")).len(), 7);
    // --animate counts the frames itself.
    let o = run(&[&once, &"--animate", &"--frames", &"3"]);
    assert_eq!(o.status.code(), Some(2));
    // A file without animation gives one frame.
    let still = background_world_file(&dir, m3g::ImageFormat::Rgb);
    let o = run(&[
        &still,
        &"--animate",
        &"--size",
        &"4x2",
        &"--format",
        &"apng",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("(1 frame, 0 ms to 0 ms) (no animation)"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn gif_output_decodes_and_matches_the_animation_length() {
    let Some(corpus) = corpus_dir() else { return };
    let dir = tmp("gif");
    let file = corpus.join("robot.m3g");
    // The animation's end as `info --json` reports it.
    let o = run(&[&"info", &"--json", &file]);
    let doc = parse_json(&String::from_utf8(o.stdout).unwrap());
    let anim = doc.get("animation");
    let end = anim.get("end").num() as u64;
    let inclusive = anim.get("end_inclusive") == &J::Bool(true);
    let step = 250;
    let expected = if inclusive {
        end / step + 1
    } else {
        end.div_ceil(step)
    };
    let out = dir.join("robot.gif");
    let o = run(&[
        &file,
        &"--animate",
        &"--step",
        &step.to_string(),
        &"--size",
        &"60x80",
        &"--format",
        &"gif",
        &"--out-dir",
        &dir,
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains(&format!("({expected} frames")));
    let dec = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(
        std::fs::File::open(&out).unwrap(),
    ))
    .unwrap();
    let frames: Vec<image::Frame> = dec.into_frames().map(|f| f.unwrap()).collect();
    assert_eq!(frames.len() as u64, expected);
    for f in &frames {
        assert_eq!(f.buffer().dimensions(), (60, 80));
        assert_eq!(f.delay().numer_denom_ms(), (250, 1));
    }
    // The first frame is the PNG render at 0 ms, up to the GIF's 256-color palette.
    let png = dir.join("robot-t0.png");
    assert!(run(&[&file, &"--size", &"60x80", &"--out", &png])
        .status
        .success());
    let png = rgb(&png);
    let gif0 = image::DynamicImage::from(frames[0].buffer().clone()).to_rgb8();
    let diff: u64 = png
        .as_raw()
        .iter()
        .zip(gif0.as_raw())
        .map(|(a, b)| a.abs_diff(*b) as u64)
        .sum();
    assert!(
        diff / (png.as_raw().len() as u64) < 8,
        "mean difference {diff}"
    );
    assert_ne!(frames[0].buffer(), frames[frames.len() / 2].buffer());
    // A single render as GIF: one frame.
    let o = run(&[
        &file,
        &"--format",
        &"gif",
        &"--size",
        &"20x20",
        &"--out",
        &dir.join("one.gif"),
    ]);
    assert!(o.status.success());
    let dec = image::codecs::gif::GifDecoder::new(std::io::BufReader::new(
        std::fs::File::open(dir.join("one.gif")).unwrap(),
    ))
    .unwrap();
    assert_eq!(dec.into_frames().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn version_and_help() {
    let o = run(&[&"--version"]);
    assert!(o.status.success());
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        format!("m3g {}\n", env!("CARGO_PKG_VERSION"))
    );
    let o = run(&[&"--help"]);
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout);
    for want in [
        "usage: m3g",
        "m3g info",
        "--out-dir",
        "--animate",
        "--format",
        "--json",
    ] {
        assert!(help.contains(want), "{want}: {help}");
    }
    let o = run(&[&"info", &"--frames", &"2", &"x.m3g"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("unknown option --frames for m3g info"));
}

// Hostile input through the tool (issue 19 item 5 and the memory budget).

/// Item 5 through the command-line tool: a 100 000-deep chain renders (on the main
/// thread's stack, where recursion overflowed at 30 000).
#[test]
fn renders_a_group_chain_100000_deep() {
    let d = tmp("deep-cli");
    let bytes = deep::on_small_stack(|| {
        m3g::writer::save(&[deep::deep_world().as_object3d()], true).unwrap()
    });
    let file = d.join("deep.m3g");
    std::fs::write(&file, bytes).unwrap();
    let out = Command::new(EXE)
        .arg(&file)
        .args(["--size", "16x16", "--out"])
        .arg(d.join("deep.png"))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = image::open(d.join("deep.png")).unwrap().to_rgb8();
    assert_eq!(png.get_pixel(8, 8).0, [255, 0, 0]);
    let _ = std::fs::remove_dir_all(&d);
}

/// `m3g --max-memory` sets the budget; past it the tool exits with code 2 and the
/// loader's message.
#[test]
fn max_memory_sets_the_budget() {
    let d = tmp("cli-budget");
    let f = d.join("image.m3g");
    std::fs::write(
        &f,
        m3g_file::file(false, &[(0, vec![m3g_file::mutable_image(1024)])]),
    )
    .unwrap();
    let out = Command::new(EXE)
        .arg(&f)
        .args(["--max-memory", "1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("memory budget"), "{err}");
    let out = Command::new(EXE)
        .arg(&f)
        .args(["--max-memory", "0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&d);
}
