#!/bin/sh
# Usage: scripts/compat-names.sh DIR
#
# Gives DIR/libGLES_CM.so the file names programs built against other OpenGL ES 1.x and EGL
# implementations look for, as symbolic links in DIR/compat:
#
#   libGLESv1_CM.so.1  libGLESv1_CM.so  libEGL.so.1  libEGL.so  ->  ../libGLES_CM.so
#
# They are links, never copies: however many of these names a process loads, the dynamic
# loader maps the one library, so GL and EGL share one global state. Running the script again
# is harmless (links are replaced, and a file in the way is replaced by the link).
set -eu

if [ "$#" -ne 1 ]; then
    echo "usage: $0 DIR   (DIR holds libGLES_CM.so, e.g. target/release)" >&2
    exit 2
fi

dir=$1
if [ ! -e "$dir/libGLES_CM.so" ]; then
    echo "$0: $dir/libGLES_CM.so not found; build the library first" >&2
    exit 1
fi

mkdir -p "$dir/compat"
for name in libGLESv1_CM.so.1 libGLESv1_CM.so libEGL.so.1 libEGL.so; do
    # -n: replace an existing link itself, never follow it into a directory.
    ln -sfn ../libGLES_CM.so "$dir/compat/$name"
done
echo "compat names in $dir/compat -> ../libGLES_CM.so"
