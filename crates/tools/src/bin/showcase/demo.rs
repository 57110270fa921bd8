//! Part one of the showcase: compiles `demo/demo.c` with the system C compiler against
//! `include/` and the `libGLES_CM.so` built beside the showcase, runs it (it renders into a
//! pbuffer and writes PAM frames) and converts its frames to PNG.

use std::path::{Path, PathBuf};
use std::process::Command;

/// What the demo reported.
pub struct DemoRun {
    /// The PNG frames, in order.
    pub frames: Vec<PathBuf>,
    /// The demo's standard output.
    pub log: String,
}

fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".into())
}

/// Builds and runs the demo, writing `out/demo-NN.png`.
pub fn run(lib_dir: &Path, out: &Path, frames: u32) -> Result<DemoRun, String> {
    let root = gles_cm_tools::repo_root();
    let source = root.join("demo/demo.c");
    let exe = out.join("demo");
    let cc = compiler();
    let compiled = Command::new(&cc)
        .args(["-std=c99", "-O2", "-Wall", "-Wextra"])
        .arg("-I")
        .arg(root.join("include"))
        .arg(&source)
        .arg("-L")
        .arg(lib_dir)
        .arg("-lGLES_CM")
        .arg(format!("-Wl,-rpath,{}", lib_dir.display()))
        .arg("-lm")
        .arg("-o")
        .arg(&exe)
        .output()
        .map_err(|e| format!("cannot run the C compiler `{cc}` (set CC to another): {e}"))?;
    if !compiled.status.success() {
        return Err(format!(
            "{cc} failed on {}:\n{}",
            source.display(),
            String::from_utf8_lossy(&compiled.stderr)
        ));
    }
    let frames_dir = out.join("demo-frames");
    std::fs::create_dir_all(&frames_dir).map_err(|e| format!("{}: {e}", frames_dir.display()))?;
    let ran = Command::new(&exe)
        .arg(&frames_dir)
        .arg(frames.to_string())
        .output()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    let log = String::from_utf8_lossy(&ran.stdout).into_owned();
    if !ran.status.success() {
        return Err(format!(
            "{} exited with {}:\n{log}{}",
            exe.display(),
            ran.status,
            String::from_utf8_lossy(&ran.stderr)
        ));
    }
    let mut pngs = Vec::new();
    for i in 0..frames {
        let pam = frames_dir.join(format!("frame-{i:02}.pam"));
        let png = out.join(format!("demo-{i:02}.png"));
        // Opaque RGB: blending leaves alpha below 1 where the panes are.
        image::DynamicImage::ImageRgba8(read_pam(&pam)?)
            .to_rgb8()
            .save(&png)
            .map_err(|e| format!("{}: {e}", png.display()))?;
        pngs.push(png);
    }
    std::fs::remove_dir_all(&frames_dir).ok();
    Ok(DemoRun { frames: pngs, log })
}

/// Reads a `P7` RGB_ALPHA image (top row first), as the demo writes it.
fn read_pam(path: &Path) -> Result<image::RgbaImage, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let end = bytes
        .windows(7)
        .position(|w| w == b"ENDHDR\n")
        .ok_or_else(|| format!("{}: PAM without ENDHDR", path.display()))?;
    let header = String::from_utf8_lossy(&bytes[..end]);
    let field = |key: &str| -> Result<u32, String> {
        header
            .lines()
            .find_map(|l| l.strip_prefix(key)?.trim().parse().ok())
            .ok_or_else(|| format!("{}: PAM without {key}", path.display()))
    };
    let (w, h) = (field("WIDTH ")?, field("HEIGHT ")?);
    image::RgbaImage::from_raw(w, h, bytes[end + 7..].to_vec())
        .ok_or_else(|| format!("{}: shorter than {w}x{h}", path.display()))
}
