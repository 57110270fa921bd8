//! `m3g-render FILE [--time MS] [--frames N --step MS] [--size WxH] [--camera USER_ID]
//! [--max-memory MIB] [--out PATH]`: loads a .m3g file, animates its (first) World to the time, renders it
//! under the conditions of the corpus reference images (Background or black, 8-bit RGBA
//! target, 16-bit depth, hints 0; default 240 × 320) and writes an RGB PNG (default: FILE
//! with `.png`).
//!
//! With `--frames N` it renders N frames at MS, MS + step, … and writes each to PATH with the
//! frame number inserted before the extension (`out-000.png`, `out-001.png`, …) plus PATH
//! itself as an animated PNG (APNG, looping, each frame shown for the step) of the sequence.
//! `--camera ID` renders through the Camera with that user ID (it must be in the World)
//! instead of the World's active camera. Runs longer than about a second print a progress
//! line on stderr. Every error (bad argument, unreadable or invalid file, no World, no such
//! camera, render or write failure) prints `m3g-render: …` on stderr and exits with code 2.

use std::collections::HashSet;
use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use GLES_CM::m3g::loader::{render_roots, Loader, RenderTarget};
use GLES_CM::m3g::{Camera, NodeExt, Object3D, Object3DExt, World};

const USAGE: &str = "\
usage: m3g-render FILE [--time MS] [--frames N --step MS] [--size WxH] [--camera USER_ID] [--target rgb|rgba] [--late-clamp] [--max-memory MIB] [--out PATH]
  FILE           a .m3g file (its first World is rendered)
  --time MS      world time of the (first) frame, default 0
  --frames N     render N frames (1..=100000) at MS, MS+step, ...; writes PATH-000.png, ...
                 and PATH itself as an animated PNG of the sequence
  --step MS      time between frames (with --frames), default 40
  --size WxH     image size, 1..=2048 each, default 240x320
  --camera ID    render through the Camera with user ID ID instead of the active camera
  --target KIND  rgb (default): a phone's Graphics target, so background images must be RGB;
                 rgba: an RGBA Image2D target, for RGBA background images
  --late-clamp   clamp lit colors after texturing, as Mesa does (the corpus references)
                 instead of right after lighting, as the specification does
  --max-memory MIB  memory budget of the load in MiB (1..=65536), default 256: a file
                 (with its external references) needing more is an error
  --out PATH     output PNG, default FILE with the extension .png";

const MAX_FRAMES: u32 = 100_000;

struct Args {
    file: PathBuf,
    time: i32,
    frames: Option<u32>,
    step: i32,
    size: (u32, u32),
    camera: Option<i32>,
    target: RenderTarget,
    late_clamp: bool,
    max_memory: u64,
    out: Option<PathBuf>,
}

fn parse_int<T: std::str::FromStr>(name: &str, v: &str, what: &str) -> Result<T, String> {
    v.parse()
        .map_err(|_| format!("{name}: {v:?} is not {what}"))
}

fn parse_args(args: impl IntoIterator<Item = String>) -> Result<Args, String> {
    let mut it = args.into_iter();
    let mut file = None;
    let mut time: i32 = 0;
    let mut frames = None;
    let mut step = None;
    let mut size = (240, 320);
    let mut camera = None;
    let mut target = RenderTarget::Graphics;
    let mut late_clamp = false;
    let mut max_memory = GLES_CM::m3g::loader::DEFAULT_MAX_MEMORY;
    let mut out = None;
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--time" => time = parse_int("--time", &value("--time")?, "an integer (milliseconds)")?,
            "--frames" => {
                let v = value("--frames")?;
                let n: u32 = parse_int("--frames", &v, "a frame count")?;
                if !(1..=MAX_FRAMES).contains(&n) {
                    return Err(format!("--frames: {n} is not in 1..={MAX_FRAMES}"));
                }
                frames = Some(n);
            }
            "--step" => {
                step = Some(parse_int(
                    "--step",
                    &value("--step")?,
                    "an integer (milliseconds)",
                )?)
            }
            "--size" => {
                let v = value("--size")?;
                let (w, h) = v
                    .split_once(['x', 'X'])
                    .ok_or_else(|| format!("--size: {v:?} is not WxH"))?;
                let (w, h): (u32, u32) = match (w.parse(), h.parse()) {
                    (Ok(w), Ok(h)) if (1..=2048).contains(&w) && (1..=2048).contains(&h) => (w, h),
                    _ => return Err(format!("--size: {v:?} is not WxH with 1..2048 each")),
                };
                size = (w, h);
            }
            "--camera" => {
                camera = Some(parse_int(
                    "--camera",
                    &value("--camera")?,
                    "an integer user ID",
                )?)
            }
            "--target" => {
                target = match value("--target")?.as_str() {
                    "rgb" => RenderTarget::Graphics,
                    "rgba" => RenderTarget::RgbaImage,
                    v => return Err(format!("--target: {v:?} is not rgb or rgba")),
                }
            }
            "--late-clamp" => late_clamp = true,
            "--max-memory" => {
                let v = value("--max-memory")?;
                let mib: u64 = parse_int("--max-memory", &v, "a size in MiB")?;
                if !(1..=65536).contains(&mib) {
                    return Err(format!("--max-memory: {mib} is not in 1..=65536"));
                }
                max_memory = mib << 20;
            }
            "--out" => out = Some(PathBuf::from(value("--out")?)),
            "-h" | "--help" => return Err(String::new()),
            s if s.starts_with('-') && s.len() > 1 => return Err(format!("unknown option {s}")),
            s => {
                if file.replace(PathBuf::from(s)).is_some() {
                    return Err("more than one FILE".into());
                }
            }
        }
    }
    if step.is_some() && frames.is_none() {
        return Err("--step needs --frames".into());
    }
    let step: i32 = step.unwrap_or(40);
    if let Some(n) = frames {
        if time
            .checked_add(step.saturating_mul(n as i32 - 1))
            .is_none()
            || step.checked_mul(n as i32 - 1).is_none()
        {
            return Err(format!(
                "--time {time} with --frames {n} --step {step} overflows the 32-bit world time"
            ));
        }
    }
    Ok(Args {
        file: file.ok_or("no FILE given")?,
        time,
        frames,
        step,
        size,
        camera,
        target,
        late_clamp,
        max_memory,
        out,
    })
}

/// The Camera with `user_id` among the objects reachable from `world`; it must be in the
/// World's scene graph. The error lists the cameras there are.
fn find_camera(world: &World, user_id: i32) -> Result<Camera, String> {
    // Handles hash and compare by identity, so their interior mutability does not matter.
    #[allow(clippy::mutable_key_type)]
    let mut seen = HashSet::new();
    let mut stack = vec![Object3D::from(world.clone())];
    let mut cameras = Vec::new();
    let mut other = None;
    while let Some(o) = stack.pop() {
        if !seen.insert(o.clone()) {
            continue;
        }
        if let Some(c) = o.downcast::<Camera>() {
            if c.user_id() == user_id {
                let mut root: Object3D = c.clone().into();
                let mut n = c.parent();
                while let Some(p) = n {
                    n = p.parent();
                    root = p.into();
                }
                if root != Object3D::from(world.clone()) {
                    return Err(format!(
                        "the Camera with user ID {user_id} is not in the World"
                    ));
                }
                return Ok(c);
            }
            cameras.push(c.user_id());
        } else if o.user_id() == user_id && other.is_none() {
            other = Some(o.class_name());
        }
        let mut refs = o.get_references();
        refs.reverse();
        stack.extend(refs);
    }
    cameras.sort_unstable();
    cameras.dedup();
    let have = if cameras.is_empty() {
        "the World has no cameras".to_string()
    } else {
        let ids: Vec<String> = cameras.iter().map(|c| c.to_string()).collect();
        format!("camera user IDs: {}", ids.join(", "))
    };
    Err(match other {
        Some(class) => format!("user ID {user_id} is a {class}, not a Camera ({have})"),
        None => format!("no Camera with user ID {user_id} ({have})"),
    })
}

/// `path` with `-NNN` inserted before its extension.
fn frame_path(path: &Path, i: u32, digits: usize) -> PathBuf {
    let stem = path
        .file_stem()
        .map_or_else(Default::default, |s| s.to_os_string());
    let mut name = stem;
    name.push(format!("-{i:0digits$}"));
    if let Some(ext) = path.extension() {
        name.push(".");
        name.push(ext);
    }
    path.with_file_name(name)
}

fn write_png(path: &Path, rgb: &[u8], (w, h): (u32, u32)) -> Result<(), String> {
    use image::ImageEncoder;
    let err = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
    let f = File::create(path).map_err(|e| err(&e))?;
    let mut bw = BufWriter::new(f);
    image::codecs::png::PngEncoder::new(&mut bw)
        .write_image(rgb, w, h, image::ExtendedColorType::Rgb8)
        .map_err(|e| err(&e))?;
    bw.flush().map_err(|e| err(&e))
}

/// A streaming animated-PNG (APNG) writer for 8-bit RGB frames of one size: the first frame
/// is the default image (IDAT), later ones are `fdAT`; the animation loops forever.
struct Apng {
    out: BufWriter<File>,
    size: (u32, u32),
    delay: (u16, u16),
    seq: u32,
    frame: u32,
}

fn crc32(parts: &[&[u8]]) -> u32 {
    let mut c = !0u32;
    for p in parts {
        for &b in *p {
            c ^= b as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
        }
    }
    !c
}

impl Apng {
    fn create(path: &Path, size: (u32, u32), frames: u32, step_ms: i32) -> std::io::Result<Apng> {
        let ms = step_ms.unsigned_abs();
        let delay = if ms <= u16::MAX as u32 {
            (ms as u16, 1000)
        } else {
            ((ms / 1000).min(u16::MAX as u32) as u16, 1)
        };
        let mut a = Apng {
            out: BufWriter::new(File::create(path)?),
            size,
            delay,
            seq: 0,
            frame: 0,
        };
        a.out
            .write_all(&[0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A])?;
        let mut ihdr = Vec::with_capacity(13);
        ihdr.extend_from_slice(&size.0.to_be_bytes());
        ihdr.extend_from_slice(&size.1.to_be_bytes());
        ihdr.extend_from_slice(&[8, 2, 0, 0, 0]); // 8-bit RGB, deflate, filter 0, no interlace
        a.chunk(b"IHDR", &ihdr)?;
        let mut actl = frames.to_be_bytes().to_vec();
        actl.extend_from_slice(&0u32.to_be_bytes()); // loop forever
        a.chunk(b"acTL", &actl)?;
        Ok(a)
    }

    fn chunk(&mut self, kind: &[u8; 4], data: &[u8]) -> std::io::Result<()> {
        self.out.write_all(&(data.len() as u32).to_be_bytes())?;
        self.out.write_all(kind)?;
        self.out.write_all(data)?;
        self.out.write_all(&crc32(&[kind, data]).to_be_bytes())
    }

    fn add_frame(&mut self, rgb: &[u8]) -> std::io::Result<()> {
        let (w, h) = self.size;
        let mut fctl = self.seq.to_be_bytes().to_vec();
        self.seq += 1;
        for v in [w, h, 0, 0] {
            fctl.extend_from_slice(&v.to_be_bytes());
        }
        fctl.extend_from_slice(&self.delay.0.to_be_bytes());
        fctl.extend_from_slice(&self.delay.1.to_be_bytes());
        fctl.extend_from_slice(&[0, 0]); // dispose none, blend source
        self.chunk(b"fcTL", &fctl)?;
        let row = w as usize * 3;
        let mut raw = Vec::with_capacity((row + 1) * h as usize);
        for r in rgb.chunks_exact(row) {
            raw.push(0); // filter: none
            raw.extend_from_slice(r);
        }
        let z = miniz_oxide::deflate::compress_to_vec_zlib(&raw, 6);
        // Chunks stay well under the 2^31 - 1 limit for 2048 × 2048 frames.
        if self.frame == 0 {
            self.chunk(b"IDAT", &z)?;
        } else {
            let mut fdat = self.seq.to_be_bytes().to_vec();
            self.seq += 1;
            fdat.extend_from_slice(&z);
            self.chunk(b"fdAT", &fdat)?;
        }
        self.frame += 1;
        Ok(())
    }

    fn finish(mut self) -> std::io::Result<()> {
        self.chunk(b"IEND", &[])?;
        self.out.flush()
    }
}

/// A progress line on stderr, shown once a run has taken over a second: rewritten in place
/// on a terminal, otherwise a line about every second.
struct Progress {
    start: Instant,
    last: Option<Instant>,
    tty: bool,
}

impl Progress {
    fn new() -> Progress {
        Progress {
            start: Instant::now(),
            last: None,
            tty: std::io::stderr().is_terminal(),
        }
    }

    fn update(&mut self, done: u32, total: u32) {
        let now = Instant::now();
        let elapsed = now - self.start;
        if elapsed < Duration::from_secs(1) && done < total {
            return;
        }
        if self.last.is_none() && done == total {
            return; // finished within a second: no progress line
        }
        let every = if self.tty { 100 } else { 1000 };
        let due = self
            .last
            .is_none_or(|l| now - l >= Duration::from_millis(every));
        if !due && done < total {
            return;
        }
        self.last = Some(now);
        let secs = elapsed.as_secs_f64();
        let eta = secs / done.max(1) as f64 * (total - done) as f64;
        let line = format!(
            "m3g-render: frame {done}/{total} ({:.0}%), {secs:.1} s, about {eta:.0} s left",
            done as f64 * 100.0 / total as f64
        );
        if self.tty {
            eprint!("\r{line}\x1b[K");
            if done == total {
                eprintln!();
            }
        } else {
            eprintln!("{line}");
        }
    }

    /// Ends an in-place line before an error message.
    fn abort(&self) {
        if self.tty && self.last.is_some() {
            eprintln!();
        }
    }
}

/// An error message, and whether it is about the arguments (then the usage line follows).
struct Failure(String, bool);

impl From<String> for Failure {
    fn from(e: String) -> Failure {
        Failure(e, false)
    }
}

fn run() -> Result<String, Failure> {
    let a = parse_args(std::env::args().skip(1)).map_err(|e| Failure(e, true))?;
    let loaded = Loader::new()
        .with_max_memory(a.max_memory)
        .load_file(&a.file)
        .map_err(|e| format!("{}: {e}", a.file.display()))?;
    let world = loaded
        .roots
        .iter()
        .find_map(|r| r.downcast::<World>())
        .ok_or_else(|| {
            let classes: Vec<&str> = loaded.roots.iter().map(|r| r.class_name()).collect();
            format!(
                "{}: no World among the root objects (they are: {})",
                a.file.display(),
                if classes.is_empty() {
                    "none".to_string()
                } else {
                    classes.join(", ")
                }
            )
        })?;
    if let Some(id) = a.camera {
        let camera = find_camera(&world, id).map_err(|e| format!("{}: {e}", a.file.display()))?;
        world.set_active_camera(&camera);
    }
    let render = |t: i32| {
        render_roots(
            &loaded.roots,
            t,
            a.size.0,
            a.size.1,
            !a.late_clamp,
            a.target,
        )
        .map_err(|e| format!("{} at {t} ms: {e}", a.file.display()))
    };
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| a.file.with_extension("png"));
    let Some(n) = a.frames else {
        write_png(&out, &render(a.time)?, a.size)?;
        return Ok(format!("wrote {}", out.display()));
    };
    let digits = (n - 1).to_string().len().max(3);
    let apng_err = |e: std::io::Error| format!("cannot write {}: {e}", out.display());
    let mut apng = Apng::create(&out, a.size, n, a.step).map_err(apng_err)?;
    let mut progress = Progress::new();
    let result = (0..n).try_for_each(|i| {
        let t = a.time + a.step * i as i32;
        let rgb = render(t)?;
        write_png(&frame_path(&out, i, digits), &rgb, a.size)?;
        apng.add_frame(&rgb).map_err(apng_err)?;
        progress.update(i + 1, n);
        Ok::<(), String>(())
    });
    if let Err(e) = result {
        progress.abort();
        drop(apng);
        let _ = std::fs::remove_file(&out);
        return Err(e.into());
    }
    apng.finish().map_err(apng_err)?;
    Ok(format!(
        "wrote {} … {} ({n} frames, {} ms to {} ms) and the animated PNG {}",
        frame_path(&out, 0, digits).display(),
        frame_path(&out, n - 1, digits).display(),
        a.time,
        a.time + a.step * (n as i32 - 1),
        out.display()
    ))
}

fn main() -> ExitCode {
    match run() {
        Ok(msg) => {
            println!("{msg}");
            ExitCode::SUCCESS
        }
        Err(Failure(e, true)) if e.is_empty() => {
            println!("{USAGE}");
            ExitCode::SUCCESS
        }
        Err(Failure(e, usage)) => {
            eprintln!("m3g-render: {e}");
            if usage {
                let line = USAGE.lines().next().unwrap_or_default();
                eprintln!("{line}\n(m3g-render --help describes the options)");
            }
            ExitCode::from(2)
        }
    }
}
