//! Fuzzes the M3G Loader (and, for inputs that load, the writer and a reload): any input must
//! give `Ok` or a `LoadError`, never a panic, hang or huge allocation.
//! Seed the corpus with `../shared/m3g-corpus/*.m3g` (see README "Fuzzing").
#![no_main]

use libfuzzer_sys::fuzz_target;
use GLES_CM::m3g::loader::Loader;
use GLES_CM::m3g::writer::save;

fuzz_target!(|data: &[u8]| {
    if let Ok(l) = Loader::new().load_bytes(data) {
        if let Ok(bytes) = save(&l.roots, false) {
            let again = Loader::new()
                .load_bytes(&bytes)
                .expect("a saved file loads again");
            assert_eq!(again.objects.len(), l.objects.len());
        }
    }
});
