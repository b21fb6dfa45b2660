#!/usr/bin/env bash
# Packs the headless GL checks into one archive that runs on a machine with nothing installed
# but glibc, libstdc++ and a GL driver (issue 39, docs/GPU.md): the machine lent with a GPU
# for a few minutes, which no package reaches.
#   bench/gpu_kit.sh pack DIR [--no-build]
# writes DIR/ivshadow-gpu-kit.tar.xz and DIR/run.sh (bench/gpu_kit_run.sh). Without --no-build
# it first brings the kit's targets of the existing Release build up to date (BUILD_DIR as for
# ./run); it never configures a build of its own.
#
# The archive mirrors the source tree (build/bin, build/lib, iv_scenes, tests/variants,
# tests/loader) because gl_tests finds its scenes, the CLI and its output folder through
# absolute paths compiled in (tests/CMakeLists.txt: IVSHADOW_SCENES_DIR, IVSHADOW_EXE, ...).
# Those paths are rewritten in the binaries, byte for byte, to a short fixed path under /tmp of
# the same length (padded with slashes, which the kernel reads as one), and run.sh points
# that path at wherever the kit was unpacked.
set -euo pipefail
# DIR as the caller named it, from where it called (BUILD_DIR, as for ./run, from the root).
caller=$PWD
cd "$(dirname "$0")/.."
export LC_ALL=C

usage() {
  echo "usage: bench/gpu_kit.sh pack DIR [--no-build]" >&2
  exit 2
}
[ "${1:-}" = pack ] && [ -n "${2:-}" ] || usage
case "$2" in
  /*) dest=$2 ;;
  *) dest=$caller/$2 ;;
esac
build_first=1
[ "${3:-}" = --no-build ] && build_first=0
[ -z "${3:-}" ] || [ "$3" = --no-build ] || usage

build=${BUILD_DIR:-build}
# The archive's limit: what travels to the lent machine is 64 MiB all told (the working tree
# included), so the kit keeps some room under it.
max_bytes=$((60 * 1024 * 1024))
# The path the binaries are rewritten to; run.sh links it to the unpacked kit.
kit_link=/tmp/ivkit

fail() {
  echo "gpu_kit.sh: $*" >&2
  exit 1
}

command -v patchelf >/dev/null ||
  fail "patchelf is missing (apt-get install -y patchelf; ./run installs it)"
command -v python3 >/dev/null || fail "python3 is missing"
cache=$build/CMakeCache.txt
[ -f "$cache" ] || fail "no build in $build: run ./run build first"
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$cache")
[ "$build_type" = Release ] ||
  fail "$build is a '$build_type' build; the kit's timings need Release"
source_dir=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$cache")
build_abs=$(cd "$build" && pwd -P)
case "$build_abs/" in
  "$source_dir"/*) build_rel=${build_abs#"$source_dir"/} ;;
  *) fail "$build is not inside its source folder $source_dir; the kit mirrors the source tree" ;;
esac
# A source folder shorter than that gets a shorter name (down to /tmp/i); shorter still, no
# path under /tmp fits in its place.
if [ ${#source_dir} -lt ${#kit_link} ]; then
  kit_link=${kit_link:0:${#source_dir}}
fi
if [ ${#source_dir} -lt 6 ]; then
  echo "gpu_kit.sh: the source folder $source_dir is shorter than /tmp/i:" \
    "its compiled-in paths cannot be rewritten" >&2
  exit 4
fi

binaries=(gl_tests ivshadow_bench ivshadow ivshadow-viewer render_scene_graph load_plugin_from_file)
if [ "$build_first" = 1 ]; then
  # The two cores are shared with other builds: one at a time.
  flock /tmp/ivshadow-build.lock make -C "$build" -j2 "${binaries[@]}" >&2
fi
for binary in "${binaries[@]}"; do
  [ -x "$build/bin/$binary" ] || fail "$build/bin/$binary is missing: build it first"
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
kit=$stage/ivshadow-gpu-kit
mkdir -p "$kit/$build_rel/bin" "$kit/$build_rel/lib" "$kit/tests"
for binary in "${binaries[@]}"; do
  cp "$build/bin/$binary" "$kit/$build_rel/bin/"
done
# The plugin under every name a scene file may load it by (the links of build/lib).
cp -P "$build"/lib/lib*.so* "$kit/$build_rel/lib/"
cp -r iv_scenes "$kit/"
cp -r tests/variants tests/loader "$kit/tests/"

# Left on the machine: glibc, the C++ runtime, and the driver. Everything else the binaries
# load comes along, also the libraries loaded by name at run time rather than linked:
# libglvnd's EGL and GL (libepoxy and Coin open them), TBB's allocator (Embree opens it).
system_only='^(linux-vdso|ld-linux|libc|libm|libmvec|libdl|libpthread|librt|libresolv|libutil'
system_only+='|libanl|libnsl|libstdc\+\+|libgcc_s)\.so'
driver='^(libEGL_|libGLX_|libgallium|libglapi|libdrm|libgbm|libLLVM|libnvidia|libcuda)'
loaded_by_name=(libEGL.so.1 libGL.so.1 libOpenGL.so.0 libGLX.so.0 libGLdispatch.so.0
                libtbbmalloc.so.2)
lib_dir=$kit/$build_rel/lib
# The loader's cache, also where /sbin is not on the PATH.
ldconfig=$(command -v ldconfig || echo /sbin/ldconfig)
for name in "${loaded_by_name[@]}"; do
  path=$("$ldconfig" -p | awk -v n="$name" '$1 == n && /x86-64/ && !found {print $NF; found = 1}')
  [ -n "$path" ] || fail "$name is not installed here"
  cp -L "$path" "$lib_dir/$name"
done
# Every library the kit's files link, to a fixed point.
while :; do
  added=0
  for file in "$kit/$build_rel"/bin/* "$lib_dir"/*; do
    [ -L "$file" ] && continue
    while read -r name path; do
      [[ $name =~ $system_only ]] && continue
      [[ $name =~ $driver ]] && fail "$(basename "$file") links the driver library $name"
      [ -e "$lib_dir/$name" ] && continue
      [ -f "$path" ] || fail "$(basename "$file") needs $name, which is not found here"
      cp -L "$path" "$lib_dir/$name"
      added=1
    done < <(ldd "$file" | awk '$2 == "=>" {print $1, $3}')
  done
  [ "$added" = 0 ] && break
done

# Smaller binaries: the kit's archive has a limit.
strip --strip-unneeded "$kit/$build_rel"/bin/* "$lib_dir"/libivshadow.so.*.*.*
for file in "$kit/$build_rel"/bin/*; do
  patchelf --set-rpath '$ORIGIN/../lib' "$file"
done
for file in "$lib_dir"/*; do
  [ -L "$file" ] && continue
  patchelf --set-rpath '$ORIGIN' "$file"
done

# The compiled-in source folder, rewritten where it starts a path.
padded=$(python3 - "$source_dir" "$kit_link" "$kit/$build_rel"/bin/* <<'EOF'
import re, sys
source, link, files = sys.argv[1], sys.argv[2], sys.argv[3:]
# /tmp + slashes + /ivkit: as long as the source folder, and the same folder to the kernel.
padded = link[:4] + "/" * (len(source) - len(link)) + link[4:]
assert len(padded) == len(source)
pattern = re.compile(re.escape(source.encode()) + rb"(?=[/\0])")
for name in files:
    with open(name, "rb") as f:
        data = f.read()
    patched, count = pattern.subn(padded.encode(), data)
    if count:
        with open(name, "wb") as f:
            f.write(patched)
print(padded)
EOF
)

sed -n "s/^bench \([a-z_]*\) '\(.*\)'$/\1 \2/p" bench/performance_docs.sh >"$kit/bench_filters.txt"
[ -s "$kit/bench_filters.txt" ] || fail "no benchmark filters found in bench/performance_docs.sh"
{
  echo "commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- 2>/dev/null || echo +)"
  echo "packed=$(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "link=$kit_link"
  echo "build=$build_rel"
} >"$kit/kit.env"
# The newest glibc each file needs: run.sh checks them against the machine's (no binutils
# there).
for file in "$kit/$build_rel"/bin/* "$lib_dir"/*; do
  [ -L "$file" ] && continue
  needs=$(objdump -T "$file" | grep -o 'GLIBC_2\.[0-9]*' | sort -uV | tail -1 || true)
  [ -z "$needs" ] || echo "$(basename "$(dirname "$file")")/$(basename "$file") $needs"
done >"$kit/glibc_needs.txt"
cp bench/gpu_kit_gl_vendor.py "$kit/gl_vendor.py"
cp bench/gpu_kit_goals.py "$kit/goals.py"
cp bench/performance_goals.py "$kit/performance_goals.py"
echo "rewrote $source_dir to $padded in the test binaries" >&2

mkdir -p "$dest"
archive=$dest/ivshadow-gpu-kit.tar.xz
# GPU_KIT_XZ_LEVEL: 6 (the default) packs about 32 MiB in under two minutes on two cores.
tar -C "$stage" -cf - ivshadow-gpu-kit | xz -T2 "-${GPU_KIT_XZ_LEVEL:-6}" >"$archive.part"
size=$(stat -c %s "$archive.part")
if [ "$size" -gt "$max_bytes" ]; then
  rm -f "$archive.part"
  fail "the archive is $((size / 1024 / 1024)) MiB, over the kit's limit of 60 MiB"
fi
mv "$archive.part" "$archive"
cp bench/gpu_kit_run.sh "$dest/run.sh"
chmod +x "$dest/run.sh"
echo "packed $archive ($((size / 1024)) KiB, $(ls "$lib_dir" | wc -l) libraries) and $dest/run.sh"
