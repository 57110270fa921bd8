//! Fuzzes external references through an in-memory file system: the input is split at
//! each `"\n--\n"` into up to six files, `/d/0.m3g`, `/d/1.m3g`, `/d/sub/2.m3g`,
//! `/d/3.png`, `/d/sub/4.m3g` and `/5.m3g` (outside the folder), and `/d/0.m3g` is loaded,
//! once with references kept inside the folder and once with them allowed anywhere; what
//! loads is rendered. Loops, fan-outs, missing files, files outside the folder and budget
//! overruns must all end in `Ok` or an `m3g::Error`.
#![no_main]

mod render;

use libfuzzer_sys::fuzz_target;
use m3g::loader::{Loader, MemoryFileSystem};

const NAMES: [&str; 6] = [
    "/d/0.m3g",
    "/d/1.m3g",
    "/d/sub/2.m3g",
    "/d/3.png",
    "/d/sub/4.m3g",
    "/5.m3g",
];

fn split(data: &[u8]) -> Vec<&[u8]> {
    let mut parts = Vec::new();
    let mut rest = data;
    while parts.len() + 1 < NAMES.len() {
        match rest.windows(4).position(|w| w == b"\n--\n") {
            Some(i) => {
                parts.push(&rest[..i]);
                rest = &rest[i + 4..];
            }
            None => break,
        }
    }
    parts.push(rest);
    parts
}

fuzz_target!(|data: &[u8]| {
    let mut fs = MemoryFileSystem::new();
    for (name, bytes) in NAMES.iter().zip(split(data)) {
        fs.insert(name, bytes.to_vec());
    }
    for allow in [false, true] {
        let loaded = Loader::new()
            .with_file_system(fs.clone())
            .with_max_memory(128 << 20)
            .allow_outside_references(allow)
            .load_file("/d/0.m3g");
        if let Ok(l) = loaded {
            render::render_loaded(&l.roots);
        }
    }
});
