//! Fuzzes the M3G Loader (and, for inputs that load, the writer and a reload, and rendering
//! what loaded): any input must give `Ok` or an `m3g::Error`, never a panic, hang or huge
//! allocation. Seed the corpus with `tests/data/m3g/*.m3g` (see README "Fuzzing").
#![no_main]

mod render;

use libfuzzer_sys::fuzz_target;
use m3g::loader::Loader;
use m3g::writer::save;

fuzz_target!(|data: &[u8]| {
    // Below the fuzzer's 512 MiB allocation limit, so that the budget, not the fuzzer,
    // stops a file that asks for too much.
    if let Ok(l) = Loader::new().with_max_memory(128 << 20).load_bytes(data) {
        if let Ok(bytes) = save(&l.roots, false) {
            let again = Loader::new()
                .load_bytes(&bytes)
                .expect("a saved file loads again");
            assert_eq!(again.objects.len(), l.objects.len());
        }
        render::render_loaded(&l.roots);
    }
});
