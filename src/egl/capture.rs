//! Frame capture for headless users: with `GLES_CM_CAPTURE=DIR` every successful
//! `eglSwapBuffers` (and with `GLES_CM_CAPTURE_FINISH=1` every `glFinish` on a thread with a
//! current surface) writes the draw surface to `DIR/frame-NNNNN.png`, so the frames of an
//! unmodified program can be looked at without a window system.
//!
//! The variables are read once, at the first swap or finish. Frames are numbered from 0 in
//! the order they are captured, across all surfaces and threads of the process. Surfaces
//! without alpha bits are written as RGB.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::{Mutex, OnceLock};

use super::surface::Surface;
use super::thread;
use gles_cm_core::target::ColorFormat;

struct Settings {
    dir: PathBuf,
    on_finish: bool,
}

fn settings() -> Option<&'static Settings> {
    static SETTINGS: OnceLock<Option<Settings>> = OnceLock::new();
    SETTINGS
        .get_or_init(|| {
            let dir = std::env::var_os("GLES_CM_CAPTURE").filter(|d| !d.is_empty())?;
            let on_finish = std::env::var("GLES_CM_CAPTURE_FINISH").is_ok_and(|v| v == "1");
            Some(Settings {
                dir: PathBuf::from(dir),
                on_finish,
            })
        })
        .as_ref()
}

/// True when swaps are captured: the caller then completes the rendering first.
pub fn enabled() -> bool {
    settings().is_some()
}

/// After a successful eglSwapBuffers of `surface`, with its rendering complete.
pub fn after_swap(surface: &Surface) {
    if let Some(s) = settings() {
        capture(s, surface);
    }
}

/// After glFinish: the calling thread's draw surface, when finish capture is on.
pub fn after_finish() {
    let Some(s) = settings().filter(|s| s.on_finish) else {
        return;
    };
    // glFinish has no error to report a failure with; a panic here must not reach C.
    let _ = crate::boundary::catch(|| {
        if let Some(d) = thread::current().and_then(|c| c.draw) {
            capture(s, &d);
        }
    });
}

fn capture(s: &Settings, surface: &Surface) {
    // One frame at a time, so that numbers are given in the order files are complete.
    static LOCK: Mutex<()> = Mutex::new(());
    static NEXT: AtomicU32 = AtomicU32::new(0);
    let _guard = LOCK.lock().unwrap_or_else(|e| e.into_inner());
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let path = s.dir.join(format!("frame-{n:05}.png"));
    if let Err(e) = std::fs::create_dir_all(&s.dir)
        .map_err(|e| e.to_string())
        .and_then(|()| write_png(surface, &path))
    {
        // The library prints nothing otherwise; here the user asked for files, and a capture
        // that silently writes none would mislead. Once per process is enough.
        static REPORTED: AtomicBool = AtomicBool::new(false);
        if !REPORTED.swap(true, Ordering::Relaxed) {
            eprintln!(
                "gles-cm: GLES_CM_CAPTURE: cannot write {}: {e}",
                path.display()
            );
        }
    }
}

fn write_png(surface: &Surface, path: &std::path::Path) -> Result<(), String> {
    let alpha = !matches!(
        surface.config.color,
        ColorFormat::Rgb565 | ColorFormat::Rgb888
    );
    let channels = if alpha { 4 } else { 3 };
    let (w, h, bytes) = {
        let target = crate::gles::Surface::target(surface)
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        let (w, h) = (target.width(), target.height());
        let mut bytes = Vec::with_capacity(w as usize * h as usize * channels);
        // Target row 0 is the bottom row; PNG rows run from the top.
        for row in target.color().chunks_exact(w.max(1) as usize).rev() {
            for px in row {
                bytes.extend_from_slice(&px.to_le_bytes()[..channels]);
            }
        }
        (w, h, bytes)
    };
    let color = if alpha {
        image::ExtendedColorType::Rgba8
    } else {
        image::ExtendedColorType::Rgb8
    };
    image::save_buffer_with_format(path, &bytes, w, h, color, image::ImageFormat::Png)
        .map_err(|e| e.to_string())
}
