//! The image files `m3g render` writes: PNG, the streaming animated PNG (APNG) writer,
//! animated GIF (through the `image` crate's encoder) and the progress line of long runs.

use std::cell::RefCell;
use std::fs::File;
use std::io::{BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::time::{Duration, Instant};

/// `path` with `-NNN` inserted before its extension.
pub fn frame_path(path: &Path, i: u32, digits: usize) -> PathBuf {
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

pub fn write_png(path: &Path, rgb: &[u8], (w, h): (u32, u32)) -> Result<(), String> {
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
pub struct Apng {
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
    pub fn create(
        path: &Path,
        size: (u32, u32),
        frames: u32,
        step_ms: i32,
    ) -> std::io::Result<Apng> {
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

    pub fn add_frame(&mut self, rgb: &[u8]) -> std::io::Result<()> {
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

    pub fn finish(mut self) -> std::io::Result<()> {
        self.chunk(b"IEND", &[])?;
        self.out.flush()
    }
}

/// A progress line on stderr, shown once a run has taken over a second: rewritten in place
/// on a terminal, otherwise a line about every second.
pub struct Progress {
    name: String,
    start: Instant,
    last: Option<Instant>,
    tty: bool,
}

impl Progress {
    /// A progress line for the file `name`.
    pub fn new(name: String) -> Progress {
        Progress {
            name,
            start: Instant::now(),
            last: None,
            tty: std::io::stderr().is_terminal(),
        }
    }

    pub fn update(&mut self, done: u32, total: u32) {
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
            "m3g: {}: frame {done}/{total} ({:.0}%), {secs:.1} s, about {eta:.0} s left",
            self.name,
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
    pub fn abort(&self) {
        if self.tty && self.last.is_some() {
            eprintln!();
        }
    }
}

/// A streaming animated GIF writer for 8-bit RGB frames (each quantized to its own
/// 256-color palette by the `image` crate), looping forever, each frame shown for the step
/// (GIF counts in hundredths of a second, so the step is rounded down to 10 ms, at least 10).
pub struct Gif {
    enc: image::codecs::gif::GifEncoder<Shared>,
    out: Shared,
    size: (u32, u32),
    delay_ms: u32,
}

impl Gif {
    pub fn create(path: &Path, size: (u32, u32), step_ms: i32) -> Result<Gif, String> {
        if size.0 > u16::MAX as u32 || size.1 > u16::MAX as u32 {
            return Err(format!("{}x{} is too large for a GIF", size.0, size.1));
        }
        let f = File::create(path).map_err(|e| e.to_string())?;
        let out = Shared(Rc::new(RefCell::new(BufWriter::new(f))));
        // Speed 10 of 1..=30: the quantizer's sampling; 1 is several times slower for
        // colors that are hard to tell apart at these sizes.
        let mut enc = image::codecs::gif::GifEncoder::new_with_speed(out.clone(), 10);
        enc.set_repeat(image::codecs::gif::Repeat::Infinite)
            .map_err(|e| e.to_string())?;
        Ok(Gif {
            enc,
            out,
            size,
            delay_ms: (step_ms.unsigned_abs() / 10 * 10).max(10),
        })
    }

    pub fn add_frame(&mut self, rgb: &[u8]) -> Result<(), String> {
        let rgba: Vec<u8> = rgb
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let buffer = image::RgbaImage::from_raw(self.size.0, self.size.1, rgba)
            .ok_or("a frame of the wrong size")?;
        let delay = image::Delay::from_numer_denom_ms(self.delay_ms, 1);
        self.enc
            .encode_frame(image::Frame::from_parts(buffer, 0, 0, delay))
            .map_err(|e| e.to_string())
    }

    /// Ends the file (the encoder writes the trailer when dropped) and flushes it.
    pub fn finish(self) -> Result<(), String> {
        drop(self.enc);
        let r = self.out.0.borrow_mut().flush();
        r.map_err(|e| e.to_string())
    }
}

/// The file behind a [`Gif`], shared with its encoder so that what the encoder writes
/// when dropped can still be flushed and its error seen.
#[derive(Clone)]
struct Shared(Rc<RefCell<BufWriter<File>>>);

impl Write for Shared {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().write(buf)
    }
    fn flush(&mut self) -> std::io::Result<()> {
        self.0.borrow_mut().flush()
    }
}
