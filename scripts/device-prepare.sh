#!/usr/bin/env bash
# Prepares what scripts/device-benchmarks.sh needs carried to a lent GPU machine (the folders are
# ignored through .git/info/exclude): .device/bin with cutaway, bench_cutaway, bench_volume and the GL test
# binaries (cutaway_gl_tests, volume_tests) from BUILD (default build), .device/lib with the shared libraries they load except glibc, libgcc and libstdc++ (that
# machine's newer ones serve), and .gl with Debian's glvnd loader packages (libEGL that finds the
# NVIDIA driver's EGL vendor library), and .shared-data, a copy of ../shared/data for the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
for ignored in /.device/ /.gl/ /.shared-data/; do grep -qxF "$ignored" .git/info/exclude || echo "$ignored" >>.git/info/exclude; done
rm -rf .device && mkdir -p .device/bin .device/lib .gl
cp "$build/bin/cutaway" "$build/bin/bench_cutaway" "$build/bin/bench_volume" "$build/bin/cutaway_gl_tests" "$build/bin/volume_tests" .device/bin/
rm -rf .shared-data && cp -rL ../shared/data .shared-data
ldd .device/bin/* | awk '/=> \//{print $3}' | sort -u | while read -r lib; do
    case $(basename "$lib") in
        libc.so* | libm.so* | libdl.so* | libpthread.so* | librt.so* | libgcc_s.so* | libstdc++.so* | ld-linux*) ;;
        *) cp -L "$lib" .device/lib/ ;;
    esac
done
if ! ls .gl/libegl1_*.deb >/dev/null 2>&1; then
    lists=$(mktemp -d)
    mkdir -p "$lists/partial"
    apt=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$lists")
    apt-get "${apt[@]}" update >/dev/null
    (cd .gl && apt-get "${apt[@]}" download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
fi
du -sh .device .gl .shared-data
