# Convenience targets. `cargo build` / `cargo test` remain the primary interface.

CARGO ?= cargo
# Where cargo builds (the same variable cargo reads).
CARGO_TARGET_DIR ?= target
export CARGO_TARGET_DIR

.PHONY: compat headers install install-only uninstall

# Release build plus the compatibility names (libGLESv1_CM.so.1, libEGL.so.1, ...) as
# symlinks to libGLES_CM.so in $(CARGO_TARGET_DIR)/release/compat.
compat:
	$(CARGO) build --release
	sh scripts/compat-names.sh $(CARGO_TARGET_DIR)/release

# Regenerates the checked-in headers under include/ from the Rust sources.
headers:
	GLES_CM_BLESS_HEADERS=1 $(CARGO) build

# Installs the stripped library (debug info in LIBDIR/.debug), its compatibility names, the
# glvnd EGL vendor (libEGL_gles_cm.so.0 and PREFIX/share/glvnd/egl_vendor.d/50_gles_cm.json),
# the headers (in PREFIX/include/gles-cm), the pkg-config files glesv1_cm.pc and egl.pc and
# m3g under DESTDIR/PREFIX; see scripts/install.sh. STRIP=0 keeps the debug info in
# place, COMPAT=0 leaves out the compatibility names (do so where glvnd is installed),
# GLVND=0 the glvnd vendor.
PREFIX ?= /usr/local
LIBDIR ?= $(PREFIX)/lib
DESTDIR ?=
export DESTDIR STRIP COMPAT GLVND
install:
	$(CARGO) build --release
	$(MAKE) install-only

# The install step alone, for a build already made (packagers build and install apart).
install-only:
	sh scripts/install.sh $(PREFIX) $(LIBDIR)

uninstall:
	sh scripts/install.sh --uninstall $(PREFIX) $(LIBDIR)
