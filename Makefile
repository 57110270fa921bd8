# Convenience targets. `cargo build` / `cargo test` remain the primary interface.

CARGO ?= cargo

.PHONY: compat headers

# Release build plus the compatibility names (libGLESv1_CM.so.1, libEGL.so.1, ...) as
# symlinks to target/release/libGLES_CM.so in target/release/compat.
compat:
	$(CARGO) build --release
	sh scripts/compat-names.sh target/release

# Regenerates the checked-in headers under include/ from the Rust sources.
headers:
	GLES_CM_BLESS_HEADERS=1 $(CARGO) build
