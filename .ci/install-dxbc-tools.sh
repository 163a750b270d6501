#!/usr/bin/env bash
# Fetches the two tools the Direct3D 12 path needs on Linux and unpacks them into one folder,
# without installing anything system-wide (docs/d3d12.md, "DXBC and the Wine run"):
#
#   vkd3d-compiler 2.1 (Debian unstable): compiles the HLSL kernels to DXBC (shader model 5.1),
#     the only bytecode Wine 8's vkd3d takes. Debian 12's vkd3d-compiler 1.2 cannot read HLSL.
#     2.1 needs unstable's libc, so that libc is unpacked beside it and the compiler runs
#     through that libc's own loader (bin/vkd3d-compiler is the wrapper that does so).
#   Mesa 25 lavapipe (bookworm-backports): Wine 8's vkd3d needs VK_EXT_descriptor_indexing,
#     which Debian 12's lavapipe (Mesa 22.3) lacks; selected with
#     VK_ICD_FILENAMES=<dir>/lvp_icd.json for the Wine run only.
#
# The folder: $LUMINA_D3D12_TOOLS_DIR, default /opt/lumina/d3d12-tools, where CMake
# (cmake/LuminaShaders.cmake) and .ci/build-d3d12-mingw.sh look. Its layout:
#   bin/vkd3d-compiler   vkd3d/ (unpacked packages)   mesa/ (unpacked)   lvp_icd.json   VERSIONS
#
# Runs as root, or as a user with sudo (only to create the folder and hand it to the user);
# apt runs with a private configuration in a temporary folder, so the system's apt sources,
# lists and package database are untouched. Needs only Debian's archive (deb.debian.org).
# Safe to run twice: a folder whose VERSIONS matches the pins below is kept.
set -euo pipefail

# The pinned packages. Unstable moves: when the archive no longer has one of these versions
# the script stops and says so; update the pin, rerun, and rerun the D3D12 tests.
mirror=${LUMINA_DEBIAN_MIRROR:-http://deb.debian.org/debian}
vkd3d_packages=(vkd3d-compiler=2.1+ds-1 libvkd3d-shader1=2.1+ds-1 libc6=2.43-7)
mesa_packages=(mesa-vulkan-drivers=25.0.7-2~bpo12+1)
dir=${LUMINA_D3D12_TOOLS_DIR:-/opt/lumina/d3d12-tools}

fail() {
    echo "install-dxbc-tools: $*" >&2
    exit 1
}

wanted_versions=$(printf '%s\n' "${vkd3d_packages[@]}" "${mesa_packages[@]}")
if [ -f "$dir/VERSIONS" ] && [ "$(cat "$dir/VERSIONS")" = "$wanted_versions" ] &&
    "$dir/bin/vkd3d-compiler" --version >/dev/null 2>&1; then
    echo "install-dxbc-tools: $dir is up to date"
    exit 0
fi
[ "$(dpkg --print-architecture)" = amd64 ] || fail "only amd64 is supported (the packages are amd64)"
command -v apt-get >/dev/null 2>&1 && command -v dpkg-deb >/dev/null 2>&1 || fail "needs apt-get and dpkg-deb (Debian)"

# The folder itself: created with sudo when its parent is not writable, then owned by the user.
if ! mkdir -p "$dir" 2>/dev/null || [ ! -w "$dir" ]; then
    [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1 || fail "cannot create $dir: run as root or with sudo," \
        "or set LUMINA_D3D12_TOOLS_DIR to a writable folder"
    sudo mkdir -p "$dir"
    sudo chown "$(id -u):$(id -g)" "$dir"
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/lumina-dxbc-tools.XXXXXX")
trap 'rm -rf "$work"' EXIT
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
[ -f "$keyring" ] || fail "$keyring missing (apt-get install debian-archive-keyring)"
cat >"$work/sources.list" <<EOF
deb [signed-by=$keyring] $mirror unstable main
deb [signed-by=$keyring] $mirror bookworm-backports main
EOF
mkdir -p "$work/lists/partial" "$work/cache/archives/partial" "$work/debs"
touch "$work/status"
apt_options=(-o "Dir::Etc::sourcelist=$work/sources.list" -o "Dir::Etc::sourceparts=-"
    -o "Dir::State::Lists=$work/lists" -o "Dir::Cache=$work/cache" -o "Dir::State::status=$work/status"
    -o "Debug::NoLocking=1" -o "APT::Sandbox::User=$(id -un)")
echo "install-dxbc-tools: reading Debian unstable and bookworm-backports indexes"
apt-get "${apt_options[@]}" -q update >"$work/update.log" 2>&1 || {
    cat "$work/update.log" >&2
    fail "apt-get update failed for $mirror (unstable, bookworm-backports)"
}
for pin in "${vkd3d_packages[@]}" "${mesa_packages[@]}"; do
    available=$(apt-cache "${apt_options[@]}" madison "${pin%%=*}" | awk '{print $3}' | sort -u | tr '\n' ' ')
    grep -qwF -- "${pin#*=}" <<<"$available" ||
        fail "Debian's archive no longer has $pin (it has: ${available:-nothing}); update the pins in $0"
done
(cd "$work/debs" && apt-get "${apt_options[@]}" -q download "${vkd3d_packages[@]}" "${mesa_packages[@]}") \
    >"$work/download.log" 2>&1 || {
    cat "$work/download.log" >&2
    fail "downloading the packages failed"
}

# Unpack beside the old contents, then move in; VERSIONS is written last, so an interrupted run
# is redone by the next.
rm -f "$dir/VERSIONS"
staging="$dir/.new"
rm -rf "$staging"
mkdir -p "$staging/bin" "$staging/vkd3d" "$staging/mesa"
for pin in "${vkd3d_packages[@]}"; do
    dpkg-deb -x "$work/debs/${pin%%=*}_"*.deb "$staging/vkd3d"
done
for pin in "${mesa_packages[@]}"; do
    dpkg-deb -x "$work/debs/${pin%%=*}_"*.deb "$staging/mesa"
done
# The wrapper finds its folder at run time, so the folder may move.
cat >"$staging/bin/vkd3d-compiler" <<'EOF'
#!/bin/sh
# vkd3d-compiler from Debian unstable, run through unstable's own libc loader (installed by
# .ci/install-dxbc-tools.sh); the host's libraries (libtinfo) come after unstable's libc.
root=$(cd "$(dirname "$0")/.." && pwd)/vkd3d
lib=$root/usr/lib/x86_64-linux-gnu
exec "$lib/ld-linux-x86-64.so.2" --library-path "$lib:/lib/x86_64-linux-gnu:/usr/lib/x86_64-linux-gnu" \
    "$root/usr/bin/vkd3d-compiler" "$@"
EOF
chmod +x "$staging/bin/vkd3d-compiler"
lvp_library="$dir/mesa/usr/lib/x86_64-linux-gnu/libvulkan_lvp.so"
[ -f "$staging/mesa/usr/lib/x86_64-linux-gnu/libvulkan_lvp.so" ] || fail "mesa-vulkan-drivers holds no libvulkan_lvp.so"
sed "s#\"library_path\": *\"[^\"]*\"#\"library_path\": \"$lvp_library\"#" \
    "$staging/mesa/usr/share/vulkan/icd.d/lvp_icd.json" >"$staging/lvp_icd.json"

"$staging/bin/vkd3d-compiler" --print-source-types 2>/dev/null | grep -q hlsl ||
    fail "the unpacked vkd3d-compiler does not run or cannot read HLSL"
rm -rf "$dir/bin" "$dir/vkd3d" "$dir/mesa" "$dir/lvp_icd.json"
mv "$staging/bin" "$staging/vkd3d" "$staging/mesa" "$staging/lvp_icd.json" "$dir/"
rmdir "$staging"
printf '%s\n' "$wanted_versions" >"$dir/VERSIONS"
echo "install-dxbc-tools: $("$dir/bin/vkd3d-compiler" --version | head -1)"
echo "install-dxbc-tools: lavapipe $(grep -o '"api_version": *"[^"]*"' "$dir/lvp_icd.json") in $dir/lvp_icd.json"
