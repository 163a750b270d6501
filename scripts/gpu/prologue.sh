# Sourced first by every command on the lent GPU machine (see docs/gpu.md): unpacks the
# Vulkan loader carried in .gl/, points the loader at NVIDIA's driver and the binaries at
# their libraries.
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
# Models that built-in scenes name by absolute path (package.sh).
if [ -d .devbin/sysroot ]; then cp -r .devbin/sysroot/. /; fi
export LD_LIBRARY_PATH=$PWD/.devbin/lib
export LUMINA_SHADER_DIR=$PWD/.devbin/shaders
export LUMINA_SOURCE_DIR=$PWD
if [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
# The NVIDIA driver's TLS library needs static TLS; loaded late (by the loader, once per
# VkInstance) it can find none left ("cannot allocate memory in static TLS block"), which
# failed every instance after the first few in the conformance tests. Preloaded, it has its own.
for tls in /usr/local/nvidia/lib64/libnvidia-tls.so.*; do
  if [ -f "$tls" ]; then export LD_PRELOAD=$tls; fi
done
