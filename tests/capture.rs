//! Frame capture (issue 23): `c_tests/capture/frames.c`, a program that knows nothing of it,
//! run with `GLES_CM_CAPTURE` (and `GLES_CM_CAPTURE_FINISH`) set, leaves one PNG per
//! `eglSwapBuffers` (and per `glFinish`) with the surface's pixels, top row first.

mod common;
use common::{lib_dir, run};

use std::path::{Path, PathBuf};
use std::process::Command;

const MANIFEST_DIR: &str = env!("CARGO_MANIFEST_DIR");

/// Builds the program once per test (each test its own executable: tests run in parallel).
fn build(name: &str) -> (PathBuf, PathBuf) {
    let dir = lib_dir().join("capture-test").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let exe = dir.join("frames");
    let lib = lib_dir();
    run(
        Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
            .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
            .arg("-I")
            .arg(Path::new(MANIFEST_DIR).join("include"))
            .arg(Path::new(MANIFEST_DIR).join("c_tests/capture/frames.c"))
            .arg("-o")
            .arg(&exe)
            .arg("-L")
            .arg(&lib)
            .arg("-lGLES_CM")
            .arg(format!("-Wl,-rpath,{}", lib.display())),
    );
    (exe, dir)
}

fn run_frames(exe: &Path, env: &[(&str, &Path)]) -> std::process::Output {
    let mut cmd = Command::new(exe);
    cmd.env("LD_LIBRARY_PATH", lib_dir())
        .env_remove("GLES_CM_CAPTURE")
        .env_remove("GLES_CM_CAPTURE_FINISH");
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().expect("run frames");
    assert!(
        out.status.success(),
        "frames failed: {}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|r| {
            r.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

fn frame(dir: &Path, n: u32) -> image::RgbaImage {
    let img = image::open(dir.join(format!("frame-{n:05}.png")))
        .unwrap_or_else(|e| panic!("frame {n}: {e}"));
    assert_eq!(
        img.color(),
        image::ColorType::Rgba8,
        "an RGBA surface keeps alpha"
    );
    img.to_rgba8()
}

const RED: [u8; 4] = [255, 0, 0, 255];
const GREEN: [u8; 4] = [0, 255, 0, 255];
const BLUE: [u8; 4] = [0, 0, 255, 255];
const YELLOW_TRANSLUCENT: [u8; 4] = [255, 255, 0, 51];

/// Red with a green 8x8 square at the top left: the orientation check.
fn assert_first_frame(img: &image::RgbaImage) {
    assert_eq!(img.dimensions(), (32, 24));
    assert_eq!(img.get_pixel(0, 0).0, GREEN, "top-left");
    assert_eq!(img.get_pixel(7, 7).0, GREEN);
    assert_eq!(img.get_pixel(8, 0).0, RED);
    assert_eq!(img.get_pixel(0, 8).0, RED);
    assert_eq!(img.get_pixel(31, 23).0, RED, "bottom-right");
}

fn assert_uniform(img: &image::RgbaImage, want: [u8; 4]) {
    assert!(img.pixels().all(|p| p.0 == want), "not all {want:?}");
}

#[test]
fn every_swap_writes_a_frame() {
    let (exe, dir) = build("swap");
    let out = dir.join("frames-out");
    run_frames(&exe, &[("GLES_CM_CAPTURE", &out)]);
    assert_eq!(files(&out), ["frame-00000.png", "frame-00001.png"]);
    assert_first_frame(&frame(&out, 0));
    assert_uniform(&frame(&out, 1), YELLOW_TRANSLUCENT);
}

#[test]
fn with_capture_finish_every_gl_finish_writes_a_frame_too() {
    let (exe, dir) = build("finish");
    let out = dir.join("frames-out");
    let one = Path::new("1");
    run_frames(
        &exe,
        &[("GLES_CM_CAPTURE", &out), ("GLES_CM_CAPTURE_FINISH", one)],
    );
    assert_eq!(
        files(&out),
        ["frame-00000.png", "frame-00001.png", "frame-00002.png"]
    );
    assert_first_frame(&frame(&out, 0));
    assert_uniform(&frame(&out, 1), BLUE);
    assert_uniform(&frame(&out, 2), YELLOW_TRANSLUCENT);
}

#[test]
fn without_the_variable_nothing_is_written() {
    let (exe, dir) = build("off");
    // GLES_CM_CAPTURE_FINISH alone does not capture; the working directory stays empty.
    let one = Path::new("1");
    let mut cmd = Command::new(&exe);
    cmd.current_dir(&dir)
        .env("LD_LIBRARY_PATH", lib_dir())
        .env_remove("GLES_CM_CAPTURE")
        .env("GLES_CM_CAPTURE_FINISH", one);
    let out = run(&mut cmd);
    assert!(out.contains("ok"), "{out}");
    assert_eq!(files(&dir), ["frames"]);
}

#[test]
fn an_unwritable_directory_is_reported_once_and_rendering_goes_on() {
    let (exe, dir) = build("unwritable");
    // A regular file where the directory would be: nothing can be created under it.
    let blocker = dir.join("blocker");
    std::fs::write(&blocker, b"not a directory").unwrap();
    let out = run_frames(&exe, &[("GLES_CM_CAPTURE", &blocker.join("frames"))]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        stderr.matches("GLES_CM_CAPTURE: cannot write").count(),
        1,
        "{stderr}"
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("ok"));
}
