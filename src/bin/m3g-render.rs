//! `m3g-render FILE [--time MS] [--size WxH] [--out PATH]`: loads a .m3g (or PNG) file,
//! animates its World to the time, renders it with the World's active camera under the
//! conditions of the corpus reference images (Background or black, 8-bit RGBA target, 16-bit
//! depth, hints 0; default 240 × 320) and writes an RGB PNG (default: FILE with `.png`).

use std::path::PathBuf;
use std::process::ExitCode;

use GLES_CM::m3g::loader::{render_roots, Loader};

const USAGE: &str = "usage: m3g-render FILE [--time MS] [--size WxH] [--out PATH]";

struct Args {
    file: PathBuf,
    time: i32,
    size: (u32, u32),
    out: Option<PathBuf>,
}

fn parse_args() -> Result<Args, String> {
    let mut it = std::env::args().skip(1);
    let mut file = None;
    let mut time = 0;
    let mut size = (240, 320);
    let mut out = None;
    while let Some(a) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "--time" => {
                let v = value("--time")?;
                time = v
                    .parse()
                    .map_err(|_| format!("--time: {v:?} is not an integer (milliseconds)"))?;
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
            "--out" => out = Some(PathBuf::from(value("--out")?)),
            "-h" | "--help" => return Err(String::new()),
            s if s.starts_with('-') => return Err(format!("unknown option {s}")),
            s => {
                if file.replace(PathBuf::from(s)).is_some() {
                    return Err("more than one FILE".into());
                }
            }
        }
    }
    Ok(Args {
        file: file.ok_or("no FILE given")?,
        time,
        size,
        out,
    })
}

fn run() -> Result<PathBuf, String> {
    let a = parse_args()?;
    let loaded = Loader::new()
        .load_file(&a.file)
        .map_err(|e| format!("{}: {e}", a.file.display()))?;
    let rgb = render_roots(&loaded.roots, a.time, a.size.0, a.size.1)
        .map_err(|e| format!("{}: {e}", a.file.display()))?;
    let out = a.out.unwrap_or_else(|| a.file.with_extension("png"));
    image::save_buffer(
        &out,
        &rgb,
        a.size.0,
        a.size.1,
        image::ExtendedColorType::Rgb8,
    )
    .map_err(|e| format!("cannot write {}: {e}", out.display()))?;
    Ok(out)
}

fn main() -> ExitCode {
    match run() {
        Ok(out) => {
            println!("wrote {}", out.display());
            ExitCode::SUCCESS
        }
        Err(e) if e.is_empty() => {
            println!("{USAGE}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("m3g-render: {e}\n{USAGE}");
            ExitCode::from(2)
        }
    }
}
