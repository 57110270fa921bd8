//! `m3g render`: the options and the rendering of one file to its image(s).

use std::path::{Path, PathBuf};

use m3g::loader::{render_roots, Loader, RenderTarget};
use m3g::Object3DExt;

use crate::output::{frame_path, write_png, Apng, Gif, Progress};
use crate::scene;

pub const MAX_FRAMES: u32 = 100_000;

/// The image format of `--format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// One PNG per frame and, for several frames, the animated PNG of them.
    Png,
    /// Only the animated PNG (a plain PNG for one frame).
    Apng,
    /// One animated GIF (one frame without an animation).
    Gif,
}

/// The options of `m3g render` (the inputs are parsed by the caller).
pub struct RenderArgs {
    pub time: Option<i32>,
    pub frames: Option<u32>,
    pub animate: bool,
    pub step: i32,
    pub size: (u32, u32),
    pub camera: Option<i32>,
    pub target: RenderTarget,
    pub late_clamp: bool,
    pub format: Format,
    pub out: Option<PathBuf>,
    pub out_dir: Option<PathBuf>,
}

fn parse_int<T: std::str::FromStr>(name: &str, v: &str, what: &str) -> Result<T, String> {
    v.parse()
        .map_err(|_| format!("{name}: {v:?} is not {what}"))
}

impl RenderArgs {
    pub fn new() -> RenderArgs {
        RenderArgs {
            time: None,
            frames: None,
            animate: false,
            step: 40,
            size: (240, 320),
            camera: None,
            target: RenderTarget::Graphics,
            late_clamp: false,
            format: Format::Png,
            out: None,
            out_dir: None,
        }
    }

    /// Takes option `a` (with its value from `value` when it has one); `Ok(false)` when
    /// `a` is not a render option.
    pub fn option(
        &mut self,
        a: &str,
        value: &mut dyn FnMut(&str) -> Result<String, String>,
        step_given: &mut bool,
    ) -> Result<bool, String> {
        match a {
            "--time" => {
                self.time = Some(parse_int(
                    "--time",
                    &value("--time")?,
                    "an integer (milliseconds)",
                )?)
            }
            "--frames" => {
                let v = value("--frames")?;
                let n: u32 = parse_int("--frames", &v, "a frame count")?;
                if !(1..=MAX_FRAMES).contains(&n) {
                    return Err(format!("--frames: {n} is not in 1..={MAX_FRAMES}"));
                }
                self.frames = Some(n);
            }
            "--animate" => self.animate = true,
            "--step" => {
                self.step = parse_int("--step", &value("--step")?, "an integer (milliseconds)")?;
                *step_given = true;
            }
            "--size" => {
                let v = value("--size")?;
                let (w, h) = v
                    .split_once(['x', 'X'])
                    .ok_or_else(|| format!("--size: {v:?} is not WxH"))?;
                self.size = match (w.parse(), h.parse()) {
                    (Ok(w), Ok(h)) if (1..=2048).contains(&w) && (1..=2048).contains(&h) => (w, h),
                    _ => return Err(format!("--size: {v:?} is not WxH with 1..2048 each")),
                };
            }
            "--camera" => {
                self.camera = Some(parse_int(
                    "--camera",
                    &value("--camera")?,
                    "an integer user ID",
                )?)
            }
            "--target" => {
                self.target = match value("--target")?.as_str() {
                    "rgb" => RenderTarget::Graphics,
                    "rgba" => RenderTarget::RgbaImage,
                    v => return Err(format!("--target: {v:?} is not rgb or rgba")),
                }
            }
            "--format" => {
                self.format = match value("--format")?.as_str() {
                    "png" => Format::Png,
                    "apng" => Format::Apng,
                    "gif" => Format::Gif,
                    v => return Err(format!("--format: {v:?} is not png, apng or gif")),
                }
            }
            "--late-clamp" => self.late_clamp = true,
            "--out" => self.out = Some(PathBuf::from(value("--out")?)),
            "--out-dir" => self.out_dir = Some(PathBuf::from(value("--out-dir")?)),
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// Checks the combinations once every option is known.
    pub fn check(&self, step_given: bool, several_inputs: bool) -> Result<(), String> {
        if self.animate && self.frames.is_some() {
            return Err(
                "--animate and --frames exclude each other (--animate counts the frames)".into(),
            );
        }
        if step_given && self.frames.is_none() && !self.animate {
            return Err("--step needs --frames or --animate".into());
        }
        if (self.frames.is_some() || self.animate) && self.step <= 0 {
            return Err(format!("--step: {} is not a positive time", self.step));
        }
        if self.out.is_some() && self.out_dir.is_some() {
            return Err("--out and --out-dir exclude each other".into());
        }
        if self.out.is_some() && several_inputs {
            return Err("--out names the output of one FILE; use --out-dir DIR for several files or a folder".into());
        }
        if let Some(n) = self.frames {
            let time = self.time.unwrap_or(0);
            if time
                .checked_add(self.step.saturating_mul(n as i32 - 1))
                .is_none()
                || self.step.checked_mul(n as i32 - 1).is_none()
            {
                return Err(format!(
                    "--time {time} with --frames {n} --step {} overflows the 32-bit world time",
                    self.step
                ));
            }
        }
        Ok(())
    }

    /// Where the output for `input` goes.
    pub fn out_path(&self, input: &Path) -> PathBuf {
        let ext = if self.format == Format::Gif {
            "gif"
        } else {
            "png"
        };
        if let Some(out) = &self.out {
            return out.clone();
        }
        match &self.out_dir {
            Some(dir) => {
                let stem = input.file_stem().unwrap_or(input.as_os_str());
                dir.join(stem).with_extension(ext)
            }
            None => input.with_extension(ext),
        }
    }
}

/// Renders `file` as `a` says; returns the line to print on success.
pub fn render_file(a: &RenderArgs, file: &Path, max_memory: u64) -> Result<String, String> {
    let loaded = Loader::new()
        .with_max_memory(max_memory)
        .load_file(file)
        .map_err(|e| e.to_string())?;
    let start = a.time.unwrap_or(0);
    let sc = scene::scene(&loaded.roots, start, a.size.0, a.size.1)?;
    if let Some(id) = a.camera {
        let camera = scene::find_camera(&sc.world, id)?;
        sc.world.set_active_camera(&camera);
    }
    let (n, note) = if a.animate {
        let tracks = scene::tracks(&[sc.world.as_object3d()]);
        match scene::animation_end(&tracks, start) {
            Some((end, inclusive)) => {
                let n = scene::frame_count(start, end, inclusive, a.step);
                if n > MAX_FRAMES as u64 {
                    return Err(format!(
                        "the animation runs from {start} ms to {end} ms: {n} frames of {} ms \
                         exceed {MAX_FRAMES}; give a larger --step",
                        a.step
                    ));
                }
                (n as u32, "")
            }
            None => (1, " (no animation)"),
        }
    } else {
        (a.frames.unwrap_or(1), "")
    };
    let roots = [sc.world.as_object3d()];
    let render = |t: i32| {
        render_roots(&roots, t, a.size.0, a.size.1, !a.late_clamp, a.target)
            .map_err(|e| format!("at {t} ms: {e}"))
    };
    let made = if sc.synthesized {
        " (no World: its root nodes under a default camera)"
    } else {
        ""
    };
    let out = a.out_path(file);
    if let Some(dir) = &a.out_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    if a.frames.is_none() && !a.animate {
        let rgb = render(start)?;
        if a.format == Format::Gif {
            let mut gif = Gif::create(&out, a.size, a.step)
                .map_err(|e| format!("cannot write {}: {e}", out.display()))?;
            gif.add_frame(&rgb)
                .and_then(|_| gif.finish())
                .map_err(|e| format!("cannot write {}: {e}", out.display()))?;
        } else {
            write_png(&out, &rgb, a.size)?;
        }
        return Ok(format!("wrote {}{made}{note}", out.display()));
    }
    let digits = (n - 1).to_string().len().max(3);
    let io_err = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", out.display());
    enum Sink {
        Apng(Apng),
        Gif(Gif),
    }
    let mut sink = match a.format {
        Format::Gif => Sink::Gif(Gif::create(&out, a.size, a.step).map_err(|e| io_err(&e))?),
        _ => Sink::Apng(Apng::create(&out, a.size, n, a.step).map_err(|e| io_err(&e))?),
    };
    let name = file.file_name().map_or_else(
        || file.display().to_string(),
        |s| s.to_string_lossy().into(),
    );
    let mut progress = Progress::new(name);
    let result = (0..n).try_for_each(|i| {
        let t = start + a.step * i as i32;
        let rgb = render(t)?;
        if a.format == Format::Png {
            write_png(&frame_path(&out, i, digits), &rgb, a.size)?;
        }
        match &mut sink {
            Sink::Apng(s) => s.add_frame(&rgb).map_err(|e| io_err(&e))?,
            Sink::Gif(s) => s.add_frame(&rgb).map_err(|e| io_err(&e))?,
        }
        progress.update(i + 1, n);
        Ok::<(), String>(())
    });
    if let Err(e) = result {
        progress.abort();
        drop(sink);
        let _ = std::fs::remove_file(&out);
        return Err(e);
    }
    match sink {
        Sink::Apng(s) => s.finish().map_err(|e| io_err(&e))?,
        Sink::Gif(s) => s.finish().map_err(|e| io_err(&e))?,
    }
    let last = start + a.step * (n as i32 - 1);
    let frames = if n == 1 {
        "1 frame".to_string()
    } else {
        format!("{n} frames")
    };
    let kind = if a.format == Format::Gif {
        "animated GIF"
    } else {
        "animated PNG"
    };
    Ok(if a.format == Format::Png {
        format!(
            "wrote {} … {} ({frames}, {start} ms to {last} ms) and the {kind} {}{made}{note}",
            frame_path(&out, 0, digits).display(),
            frame_path(&out, n - 1, digits).display(),
            out.display()
        )
    } else {
        format!(
            "wrote the {kind} {} ({frames}, {start} ms to {last} ms){made}{note}",
            out.display()
        )
    })
}
