# Convenience targets. `cargo build` / `cargo test` remain the primary interface.

CARGO ?= cargo

.PHONY: compat headers install

# Release build plus the compatibility names (libGLESv1_CM.so.1, libEGL.so.1, ...) as
# symlinks to target/release/libGLES_CM.so in target/release/compat.
compat:
	$(CARGO) build --release
	sh scripts/compat-names.sh target/release

# Regenerates the checked-in headers under include/ from the Rust sources.
headers:
	GLES_CM_BLESS_HEADERS=1 $(CARGO) build

# Installs the library, the compatibility names, the headers and pkg-config files
# (glesv1_cm.pc, egl.pc) under PREFIX.
PREFIX ?= /usr/local
install:
	$(CARGO) build --release
	sh scripts/install.sh $(PREFIX)
