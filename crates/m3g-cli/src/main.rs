//! `m3g`: the command-line tool for .m3g files (M3G 1.1 / JSR-184 scenes from phone games).
//!
//! * `m3g [render] FILE|DIR… [options]` renders each file: its first World, or, for a file
//!   without one (only Groups, Meshes, Sprite3Ds at the root, as games often ship), its
//!   root nodes in a World under a default perspective camera framing their bounds and a
//!   default directional and ambient light. Under the conditions of the corpus reference
//!   images (Background or black, 8-bit RGBA target, 16-bit depth, hints 0; default
//!   240 × 320) it writes an RGB PNG (default: FILE with `.png`, or DIR/NAME.png with
//!   `--out-dir DIR`). `--frames N --step MS` renders N frames and writes each PNG with the
//!   frame number before the extension plus the sequence as an animated PNG; `--animate`
//!   derives N from the animations' length; `--format apng|gif` writes only an animated
//!   PNG or an animated GIF.
//! * `m3g info FILE|DIR… [--json]` prints each file's object graph: an indented tree of
//!   class, index in the file, user ID, key parameters and references, and the animation
//!   tracks with when they are over; as JSON with `--json`.
//!
//! A folder stands for the .m3g files in it (not its subfolders), in name order. A file
//! that fails (unreadable, invalid, nothing to render, render or write failure) prints
//! `m3g: FILE: …` on stderr and the others go on; the run then ends with a summary line
//! naming the failed files and exit code 2. Argument errors print the usage line and
//! exit with code 2 before any file is read.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

mod info;
mod json;
mod output;
mod render;
mod scene;

use render::RenderArgs;

const USAGE: &str = "\
usage: m3g [render] FILE|DIR... [--time MS] [--frames N | --animate] [--step MS] [--size WxH] [--camera USER_ID] [--target rgb|rgba] [--late-clamp] [--format png|apng|gif] [--max-memory MIB] [--out PATH | --out-dir DIR]
       m3g info FILE|DIR... [--json] [--max-memory MIB]
       m3g --help | --version

m3g render (the default command) renders each .m3g file (a DIR: every .m3g file in it):
its first World, or, in a file without a World, its root nodes (Groups, Meshes, Sprite3Ds)
in a World under a default perspective camera that frames their bounds, with a default
directional light and an ambient light unless the nodes bring a Light.
  --time MS      world time of the (first) frame, default 0
  --frames N     render N frames (1..=100000) at MS, MS+step, ...; writes OUT-000.png, ...
                 and OUT itself as an animated PNG of the sequence
  --animate      like --frames, with N covering the whole animation from MS: until the
                 last animation track is over (one period of a looping sequence, a one-shot
                 sequence's end, or its controller's active interval's end)
  --step MS      time between frames (with --frames or --animate), default 40
  --size WxH     image size, 1..=2048 each, default 240x320
  --camera ID    render through the Camera with user ID ID instead of the active camera
  --target KIND  rgb (default): a phone's Graphics target, so background images must be RGB;
                 rgba: an RGBA Image2D target, for RGBA background images
  --late-clamp   clamp lit colors after texturing, as Mesa does (the corpus references)
                 instead of right after lighting, as the specification does
  --format KIND  png (default): PNG frames (+ the animated PNG for a sequence);
                 apng: only the animated PNG; gif: one (animated) GIF, OUT ending in .gif
  --max-memory MIB  memory budget of a load in MiB (1..=65536), default 256: a file
                 (with its external references) needing more is an error
  --out PATH     the output of the one FILE, default FILE with the extension .png (.gif)
  --out-dir DIR  write every output into DIR (created if missing), named after its input:
                 DIR/NAME.png for NAME.m3g

m3g info prints each file's object graph: an indented tree of objects (#index in the file,
class, user ID, key parameters, references; an object met again shows as '(above)') and its
animation tracks with the time each is over.
  --json         the same as JSON: one object for one FILE, an array for several or a DIR

A file that fails prints 'm3g: FILE: reason' on stderr and the others go on; the exit code
is then 2. Argument errors exit with code 2 before any file is read.";

/// An error message, and whether it is about the arguments (then the usage line follows).
struct Failure(String, bool);

impl From<String> for Failure {
    fn from(e: String) -> Failure {
        Failure(e, false)
    }
}

enum Command {
    Render(Box<RenderArgs>),
    Info { json: bool },
}

struct Args {
    command: Command,
    inputs: Vec<PathBuf>,
    max_memory: u64,
}

/// What the command line asks for; `Ok(None)` after `--help` or `--version` was printed.
fn parse_args(args: Vec<String>) -> Result<Option<Args>, String> {
    let mut it = args.into_iter().peekable();
    let info = match it.peek().map(String::as_str) {
        Some("info") => true,
        Some("render") => false,
        Some("help") => {
            println!("{USAGE}");
            return Ok(None);
        }
        _ => false,
    };
    if matches!(it.peek().map(String::as_str), Some("info" | "render")) {
        it.next();
    }
    let mut render = RenderArgs::new();
    let mut json = false;
    let mut inputs = Vec::new();
    let mut max_memory = m3g::loader::DEFAULT_MAX_MEMORY;
    let mut step_given = false;
    let mut only_inputs = false;
    while let Some(a) = it.next() {
        if only_inputs {
            inputs.push(PathBuf::from(a));
            continue;
        }
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        match a.as_str() {
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(None);
            }
            "-V" | "--version" => {
                println!("m3g {}", env!("CARGO_PKG_VERSION"));
                return Ok(None);
            }
            "--max-memory" => {
                let v = value("--max-memory")?;
                let mib: u64 = v
                    .parse()
                    .map_err(|_| format!("--max-memory: {v:?} is not a size in MiB"))?;
                if !(1..=65536).contains(&mib) {
                    return Err(format!("--max-memory: {mib} is not in 1..=65536"));
                }
                max_memory = mib << 20;
            }
            "--json" if info => json = true,
            "--" => only_inputs = true,
            s if s.starts_with('-') && s.len() > 1 => {
                if info || !render.option(s, &mut value, &mut step_given)? {
                    let cmd = if info { "m3g info" } else { "m3g render" };
                    return Err(format!("unknown option {s} for {cmd}"));
                }
            }
            s => inputs.push(PathBuf::from(s)),
        }
    }
    if inputs.is_empty() {
        return Err("no FILE given".into());
    }
    let command = if info {
        Command::Info { json }
    } else {
        render.check(
            step_given,
            inputs.len() > 1 || inputs.iter().any(|p| p.is_dir()),
        )?;
        Command::Render(Box::new(render))
    };
    Ok(Some(Args {
        command,
        inputs,
        max_memory,
    }))
}

/// The files the inputs stand for: a folder's .m3g files (any case of the extension) in
/// name order, other paths as given. A folder that cannot be read or holds no .m3g file
/// is a failure of its own.
fn expand(inputs: &[PathBuf]) -> Vec<Result<PathBuf, (PathBuf, String)>> {
    let mut out = Vec::new();
    for p in inputs {
        if !p.is_dir() {
            out.push(Ok(p.clone()));
            continue;
        }
        let entries = match std::fs::read_dir(p) {
            Ok(e) => e,
            Err(e) => {
                out.push(Err((p.clone(), format!("cannot read the folder: {e}"))));
                continue;
            }
        };
        let mut files: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|f| f.is_file() && f.extension().is_some_and(|e| e.eq_ignore_ascii_case("m3g")))
            .collect();
        files.sort();
        if files.is_empty() {
            out.push(Err((p.clone(), "no .m3g files in this folder".into())));
        }
        out.extend(files.into_iter().map(Ok));
    }
    out
}

fn run() -> Result<(), Failure> {
    let Some(args) =
        parse_args(std::env::args().skip(1).collect()).map_err(|e| Failure(e, true))?
    else {
        return Ok(());
    };
    let files = expand(&args.inputs);
    let total = files.len();
    let mut failed: Vec<PathBuf> = Vec::new();
    let mut fail = |path: &Path, e: &str| {
        eprintln!("m3g: {}: {e}", path.display());
        failed.push(path.to_path_buf());
    };
    match &args.command {
        Command::Render(r) => {
            // Outputs named after their inputs must not overwrite each other.
            let mut outputs: HashMap<PathBuf, PathBuf> = HashMap::new();
            for f in &files {
                let file = match f {
                    Ok(f) => f,
                    Err((p, e)) => {
                        fail(p, e);
                        continue;
                    }
                };
                let out = r.out_path(file);
                if let Some(first) = outputs.get(&out) {
                    fail(
                        file,
                        &format!(
                            "its output {} is that of {} already",
                            out.display(),
                            first.display()
                        ),
                    );
                    continue;
                }
                outputs.insert(out, file.clone());
                match render::render_file(r, file, args.max_memory) {
                    Ok(msg) => println!("{}: {msg}", file.display()),
                    Err(e) => fail(file, &e),
                }
            }
        }
        Command::Info { json: as_json } => {
            let mut docs = Vec::new();
            let mut first = true;
            for f in &files {
                let file = match f {
                    Ok(f) => f,
                    Err((p, e)) => {
                        fail(p, e);
                        continue;
                    }
                };
                let loaded = match m3g::Loader::new()
                    .with_max_memory(args.max_memory)
                    .load_file(file)
                {
                    Ok(l) => l,
                    Err(e) => {
                        fail(file, &e.to_string());
                        continue;
                    }
                };
                if *as_json {
                    docs.push(info::json_report(file, &loaded));
                } else {
                    if !first {
                        println!();
                    }
                    first = false;
                    print!("{}", info::text_report(file, &loaded));
                }
            }
            if *as_json {
                let single = args.inputs.len() == 1 && !args.inputs[0].is_dir();
                let doc = if single && docs.len() == 1 {
                    docs.pop().unwrap_or(json::Json::Null)
                } else {
                    json::Json::Arr(docs)
                };
                if !(single && failed.len() == 1) {
                    println!("{}", doc.pretty());
                }
            }
        }
    }
    if failed.is_empty() {
        return Ok(());
    }
    if total == 1 {
        // The file's own message said it all.
        return Err(Failure(String::new(), false));
    }
    let names: Vec<String> = failed.iter().map(|p| p.display().to_string()).collect();
    Err(Failure(
        format!(
            "{} of {total} files failed: {}",
            failed.len(),
            names.join(", ")
        ),
        false,
    ))
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure(e, usage)) => {
            if !e.is_empty() {
                eprintln!("m3g: {e}");
            }
            if usage {
                let line = USAGE.lines().next().unwrap_or_default();
                eprintln!("{line}\n(m3g --help describes the commands and options)");
            }
            ExitCode::from(2)
        }
    }
}
