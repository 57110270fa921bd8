//! M3G 1.1 (JSR-184) in Rust.
