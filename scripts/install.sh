#!/bin/sh
# Usage: scripts/install.sh [--uninstall] PREFIX [LIBDIR]
#
# Installs a release build (cargo build --release) under DESTDIR/PREFIX:
#
#   LIBDIR/libGLES_CM.so.1                the library (SONAME libGLES_CM.so.1), stripped
#   LIBDIR/.debug/libGLES_CM.so.1.debug   its debug info, found by gdb through .gnu_debuglink
#   LIBDIR/libGLES_CM.so                  -> libGLES_CM.so.1, for -lGLES_CM
#   LIBDIR/libGLESv1_CM.so.1, libGLESv1_CM.so, libEGL.so.1, libEGL.so
#                                         -> libGLES_CM.so.1, the compatibility names
#   LIBDIR/libEGL_gles_cm.so.0            -> libGLES_CM.so.1, the glvnd EGL vendor library
#   PREFIX/share/glvnd/egl_vendor.d/50_gles_cm.json
#                                         glvnd's vendor file, naming LIBDIR/libEGL_gles_cm.so.0
#   LIBDIR/pkgconfig/glesv1_cm.pc, egl.pc
#   PREFIX/include/gles-cm/{GLES,EGL,KHR}/*.h
#   PREFIX/bin/m3g                        (stripped, its debug info in PREFIX/bin/.debug)
#
# LIBDIR defaults to PREFIX/lib. The headers go into a private directory that only the
# pkg-config files name (`pkg-config --cflags glesv1_cm egl`), so they never shadow the system's
# Khronos headers in PREFIX/include.
#
# Environment:
#   DESTDIR=dir        stage into dir (the .pc files still say PREFIX), as packagers do
#   STRIP=0            install unstripped, with no .debug files
#   COMPAT=0           leave out the compatibility names (for machines with glvnd, whose
#                      libEGL.so.1 and libGLESv1_CM.so.1 they would shadow in LIBDIR)
#   GLVND=0            leave out the glvnd vendor library and its vendor file
#   CARGO_TARGET_DIR   where cargo put the build (default: target/ of this repository)
#   GLES_CM_LIB=path   the library file to install (default: the release build's)
#
# --uninstall removes exactly the files above (and the directories that become empty).
set -eu

mode=install
if [ "${1:-}" = "--uninstall" ]; then
    mode=uninstall
    shift
fi
if [ "$#" -lt 1 ]; then
    echo "usage: $0 [--uninstall] PREFIX [LIBDIR]   (build first: cargo build --release)" >&2
    exit 2
fi
prefix=$1
libdir=${2:-$prefix/lib}
destdir=${DESTDIR:-}
here=$(cd "$(dirname "$0")/.." && pwd)
target=${CARGO_TARGET_DIR:-$here/target}
lib=${GLES_CM_LIB:-$target/release/libGLES_CM.so}
bin=$target/release/m3g

soname=libGLES_CM.so.1
compat="libGLESv1_CM.so.1 libGLESv1_CM.so libEGL.so.1 libEGL.so"
[ "${COMPAT:-1}" = 0 ] && compat=""
# The glvnd vendor is the same library under the name glvnd's convention gives vendors
# (libEGL_<vendor>.so.0): a link, so a process that also loads libGLES_CM.so.1 maps one object.
vendor=libEGL_gles_cm.so.0
vendor_json=50_gles_cm.json
glvnd=1
[ "${GLVND:-1}" = 0 ] && glvnd=0
d_vendor=$destdir$prefix/share/glvnd/egl_vendor.d
d_lib=$destdir$libdir
d_inc=$destdir$prefix/include/gles-cm
d_bin=$destdir$prefix/bin

if [ "$mode" = uninstall ]; then
    rm -f "$d_lib/$soname" "$d_lib/.debug/$soname.debug" "$d_lib/libGLES_CM.so" \
        "$d_lib/pkgconfig/glesv1_cm.pc" "$d_lib/pkgconfig/egl.pc" \
        "$d_bin/m3g" "$d_bin/.debug/m3g.debug"
    rm -f "$d_vendor/$vendor_json"
    for name in libGLESv1_CM.so.1 libGLESv1_CM.so libEGL.so.1 libEGL.so $vendor; do
        # Only our links: another implementation's file of that name stays.
        if [ -L "$d_lib/$name" ] && [ "$(readlink "$d_lib/$name")" = "$soname" ]; then
            rm -f "$d_lib/$name"
        fi
    done
    rm -rf "$d_inc"
    for dir in "$d_lib/.debug" "$d_lib/pkgconfig" "$d_bin/.debug" "$d_vendor" \
        "$destdir$prefix/share/glvnd"; do
        rmdir "$dir" 2>/dev/null || true
    done
    echo "uninstalled from $destdir$prefix"
    exit 0
fi

[ -e "$lib" ] || { echo "$0: $lib not found; run cargo build --release" >&2; exit 1; }
[ -e "$bin" ] || { echo "$0: $bin not found; run cargo build --release" >&2; exit 1; }

# install_elf SRC DIR NAME: copies SRC to DIR/NAME; unless STRIP=0, its debug info goes to
# DIR/.debug/NAME.debug and the installed file keeps only a link to it (.gnu_debuglink).
install_elf() {
    mkdir -p "$2"
    rm -f "$2/$3"
    cp "$1" "$2/$3"
    if [ "${STRIP:-1}" != 0 ]; then
        mkdir -p "$2/.debug"
        objcopy --only-keep-debug "$2/$3" "$2/.debug/$3.debug"
        chmod 644 "$2/.debug/$3.debug"
        # --strip-unneeded keeps the dynamic symbol table, which is the library's interface.
        strip --strip-unneeded "$2/$3"
        # Run from DIR so the link records the bare name gdb looks for in DIR/.debug.
        (cd "$2/.debug" && objcopy --add-gnu-debuglink="$3.debug" "../$3")
    fi
}

install_elf "$lib" "$d_lib" "$soname"
chmod 755 "$d_lib/$soname"
ln -sfn "$soname" "$d_lib/libGLES_CM.so"
for name in $compat; do
    ln -sfn "$soname" "$d_lib/$name"
done
if [ "$glvnd" = 1 ]; then
    ln -sfn "$soname" "$d_lib/$vendor"
    # library_path is absolute: glvnd dlopen()s it, and LIBDIR need not be on the loader's
    # search path (PREFIX=/opt/...). The file is glvnd's format version 1.0.0.
    mkdir -p "$d_vendor"
    cat > "$d_vendor/$vendor_json" <<JSON
{
    "file_format_version" : "1.0.0",
    "ICD" : {
        "library_path" : "$libdir/$vendor"
    }
}
JSON
    chmod 644 "$d_vendor/$vendor_json"
fi
install_elf "$bin" "$d_bin" m3g
chmod 755 "$d_bin/m3g"

rm -rf "$d_inc"
mkdir -p "$d_inc"
cp -R "$here/include/GLES" "$here/include/EGL" "$here/include/KHR" "$d_inc/"
find "$d_inc" -type f -exec chmod 644 {} +

# The .pc versions are the API versions (what `pkg-config --atleast-version` is asked about);
# the package's own version is the gles_cm_version variable.
package_version=$(sed -n 's/^version = "\(.*\)"/\1/p' "$here/Cargo.toml" | head -1)
mkdir -p "$d_lib/pkgconfig"
for pc in "glesv1_cm:1.1:OpenGL ES 1.1 Common" "egl:1.5:EGL 1.5, headless"; do
    name=${pc%%:*}
    rest=${pc#*:}
    version=${rest%%:*}
    cat > "$d_lib/pkgconfig/$name.pc" <<PC
prefix=$prefix
libdir=$libdir
includedir=\${prefix}/include/gles-cm
gles_cm_version=$package_version

Name: $name
Description: ${rest#*:} (gles-cm $package_version software renderer)
Version: $version
Libs: -L\${libdir} -lGLES_CM
Cflags: -I\${includedir}
PC
    chmod 644 "$d_lib/pkgconfig/$name.pc"
done
echo "installed into $destdir$prefix (library in $destdir$libdir)"
