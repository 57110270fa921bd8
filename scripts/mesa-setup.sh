#!/bin/sh
# Installs what is missing of Mesa's GLES 1.1 + EGL (llvmpipe and softpipe) with its
# development headers and a C compiler, on Debian: the optional oracle of the differential
# C tests and the drop-in test. libegl-dev and libgles-dev also bring the Khronos headers
# (GLES/glext.h, EGL/eglext.h) that tests/headers.rs compares ours with. libegl1 and libgles1
# are glvnd's libEGL.so.1 and libGLESv1_CM.so.1, which tests/glvnd.rs drives our glvnd vendor
# through. Idempotent; tests without them say "skipped".
set -eu
pkgs="libegl1 libgles1 libegl-mesa0 libgl1-mesa-dri libegl-dev libgles-dev gcc libc6-dev"
missing=""
for p in $pkgs; do
    [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" = "install ok installed" ] ||
        missing="$missing $p"
done
if [ -n "$missing" ]; then
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
fi
ls /usr/lib/*/libGLESv1_CM.so /usr/lib/*/libEGL.so /usr/include/GLES/gl.h >/dev/null
