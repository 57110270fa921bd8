#!/bin/sh
# Usage: scripts/install.sh PREFIX [LIBDIR]    (GLES_CM_LIB=path overrides the library installed)
#
# Installs a release build: PREFIX/lib/libGLES_CM.so with the compatibility names beside it
# (libGLESv1_CM.so.1, libGLESv1_CM.so, libEGL.so.1, libEGL.so, all links to it), the headers
# under PREFIX/include, and pkg-config files glesv1_cm.pc and egl.pc, so that
# `cc app.c $(pkg-config --cflags --libs glesv1_cm egl)` links against this library.
set -eu

if [ "$#" -lt 1 ]; then
    echo "usage: $0 PREFIX [LIBDIR]   (build first: cargo build --release)" >&2
    exit 2
fi
prefix=$1
libdir=${2:-$prefix/lib}
here=$(cd "$(dirname "$0")/.." && pwd)
lib=${GLES_CM_LIB:-$here/target/release/libGLES_CM.so}
[ -e "$lib" ] || { echo "$0: $lib not found; run cargo build --release" >&2; exit 1; }

mkdir -p "$libdir/pkgconfig" "$prefix/include"
cp "$lib" "$libdir/libGLES_CM.so"
for name in libGLESv1_CM.so.1 libGLESv1_CM.so libEGL.so.1 libEGL.so; do
    ln -sfn libGLES_CM.so "$libdir/$name"
done
cp -R "$here/include/GLES" "$here/include/EGL" "$here/include/KHR" "$prefix/include/"

version=$(sed -n 's/^version = "\(.*\)"/\1/p' "$here/Cargo.toml" | head -1)
for pc in glesv1_cm:"OpenGL ES 1.1 Common (gles-cm software renderer)" \
          egl:"EGL 1.4 (gles-cm, headless)"; do
    name=${pc%%:*}
    cat > "$libdir/pkgconfig/$name.pc" <<PC
prefix=$prefix
libdir=$libdir
includedir=\${prefix}/include

Name: $name
Description: ${pc#*:}
Version: $version
Libs: -L\${libdir} -lGLES_CM
Cflags: -I\${includedir}
PC
done
echo "installed into $prefix (library in $libdir)"
