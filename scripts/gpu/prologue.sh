# Sourced first by every command on the lent GPU machine (see docs/gpu.md): unpacks the
# Vulkan loader carried in .gl/, points the loader at NVIDIA's driver and the binaries at
# their libraries.
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
export LD_LIBRARY_PATH=$PWD/.devbin/lib
export LUMINA_SHADER_DIR=$PWD/.devbin/shaders
export LUMINA_SOURCE_DIR=$PWD
if [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
