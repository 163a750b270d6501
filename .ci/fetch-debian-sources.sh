#!/usr/bin/env bash
# Fetches and unpacks the Debian source packages the Windows cross build compiles itself,
# because Debian ships no MinGW-w64 build of them (only Linux ones: libglfw3-dev, libimgui-dev):
#   glfw3  -> DEST/glfw3   (GLFW, built with its own CMakeLists.txt for Windows)
#   imgui  -> DEST/imgui   (Dear ImGui and its GLFW backend, the version of libimgui-dev)
# Sources come from the running Debian release's archive through apt (deb-src, in a private apt
# state under DEST/apt: the system's apt configuration is not touched, no root needed where
# the folders are writable). apt checks every file against the archive's signed Sources index.
# Nothing is fetched when DEST already holds both.
#
#   .ci/fetch-debian-sources.sh build-mingw/debian-sources
set -euo pipefail

dest=${1:?usage: fetch-debian-sources.sh DEST}
packages=(glfw3 imgui)

have_all=1
for p in "${packages[@]}"; do
    [ -f "$dest/$p/.unpacked" ] || have_all=0
done
if [ "$have_all" = 1 ]; then
    echo "fetch-debian-sources: ${packages[*]} already in $dest"
    exit 0
fi
command -v dpkg-source >/dev/null || { echo "fetch-debian-sources: dpkg-source not found (apt-get install dpkg-dev)" >&2; exit 1; }

. /etc/os-release
suite=${VERSION_CODENAME:?no VERSION_CODENAME in /etc/os-release}
mkdir -p "$dest/apt/lists/partial" "$dest/apt/cache/archives/partial" "$dest/download"
dest=$(cd "$dest" && pwd)
cat >"$dest/apt/debian.sources" <<SOURCES
Types: deb-src
URIs: ${LUMINA_DEBIAN_MIRROR:-http://deb.debian.org/debian}
Suites: $suite
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
apt_opts=(-q -o "Dir::Etc::SourceList=$dest/apt/debian.sources" -o Dir::Etc::SourceParts=/nonexistent
    -o "Dir::State::Lists=$dest/apt/lists" -o "Dir::Cache=$dest/apt/cache" -o Debug::NoLocking=1
    -o APT::Sandbox::User=root)
apt-get "${apt_opts[@]}" update >/dev/null
cd "$dest/download"
apt-get "${apt_opts[@]}" source --download-only "${packages[@]}"
for p in "${packages[@]}"; do
    dsc=$(ls "$p"_*.dsc | sort -V | tail -n 1)
    rm -rf "${dest:?}/$p"
    # --no-check: apt has verified the files against the signed index; dpkg-source would want
    # the debian-keyring package to check the .dsc signature again.
    dpkg-source --no-check -x "$dsc" "$dest/$p" >/dev/null
    echo "${dsc%.dsc}" >"$dest/$p/.unpacked"
    echo "fetch-debian-sources: $(cat "$dest/$p/.unpacked") -> $dest/$p"
done
