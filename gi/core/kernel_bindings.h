#pragma once
// A kernel's resources as its SPIR-V declares them, and the check that a pass binds each of them:
// the registers of a pass's C++ (`.read(3, ...)`) and of its HLSL (`register(t3)`) are matched
// when the pipeline is created, so a mismatch is an error that names both sides instead of a
// validation message or a wrong image (docs/binding.md, "Checked at pipeline creation").
#include "gi/core/pipeline_cache.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::gi {

// What the kernel declares at a register, as far as a binding must agree with it.
enum class KernelResourceKind : uint8_t {
    ConstantBuffer, // b: cbuffer, ConstantBuffer<T>
    Texture,        // t: Texture2D, Texture3D, TextureCube, ... (sampled image)
    Buffer,         // t or u: StructuredBuffer, ByteAddressBuffer and their RW forms
    StorageTexture, // u: RWTexture2D, RWTexture3D, RWTexture2DArray
    Sampler,        // s: SamplerState, SamplerComparisonState
};

struct KernelResource {
    std::string name; // the HLSL variable, e.g. "gProbes"
    uint32_t space = 0;
    char registerClass = 'b'; // 'b', 't', 'u' or 's'
    uint32_t reg = 0;         // within its class: register(t3) is 3
    KernelResourceKind kind = KernelResourceKind::ConstantBuffer;
};

// The descriptor-bound resources of a SPIR-V module made by the build (glslang keeps only those
// the entry point uses). The register comes back from the binding number by the build's shifts:
// b 0, t 100, u 200, s 300. Throws rhi::Error naming `kernel` on a malformed module.
std::vector<KernelResource> kernelResources(std::string_view kernel, std::span<const uint32_t> spirv);

// Throws rhi::Error naming the kernel's variable and register and what the pass bound there (or
// the registers it did bind) when a resource the kernel uses is not bound, or is bound as a
// different kind (a buffer where the kernel reads a texture). A pass may bind more than its
// kernel uses (binding helpers shared by several kernels do).
void checkKernelBindings(std::string_view kernel, const std::vector<KernelResource>& resources,
                         const SpaceBindings& bindings);

// The SPIR-V file of `kernel` in the build's shader folder, read as words; empty when the build
// made none (a D3D12-only folder).
std::vector<uint32_t> readKernelSpirv(const std::string& directory, std::string_view kernel);

} // namespace lumina::gi
