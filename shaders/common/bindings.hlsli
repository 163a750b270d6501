#ifndef LUMINA_BINDINGS_HLSLI
#define LUMINA_BINDINGS_HLSLI
// Binding macros that let one HLSL source compile with glslang, DXC -spirv and DXC -> DXIL.
// The build defines LUMINA_SPIRV=1 for both SPIR-V compilers (docs/binding.md).

// Push constants: Vulkan push constants; on D3D12, root constants at register b0 in a
// space of their own (LUMINA_PUSH_CONSTANT_SPACE), which the root signature reserves.
#define LUMINA_PUSH_CONSTANT_SPACE space999
#if defined(LUMINA_SPIRV)
#define LUMINA_PUSH_CONSTANTS(Type, name) [[vk::push_constant]] ConstantBuffer<Type> name
#else
#define LUMINA_PUSH_CONSTANTS(Type, name) ConstantBuffer<Type> name : register(b0, LUMINA_PUSH_CONSTANT_SPACE)
#endif

// Storage-image formats: glslang guesses the SPIR-V format from the element type
// (RWTexture2D<float4> would be rgba32f even for an rgba16f texture), so every typed UAV
// states its format: LUMINA_UAV_FORMAT(rgba16f) RWTexture2D<float4> gOut : register(u0);
#if defined(LUMINA_SPIRV) && defined(__hlsl_dx_compiler)
#define LUMINA_UAV_FORMAT(fmt) [[vk::image_format(#fmt)]]
#elif defined(LUMINA_SPIRV)
#define LUMINA_UAV_FORMAT(fmt) [[spv::format_##fmt]]
#else
#define LUMINA_UAV_FORMAT(fmt)
#endif

#endif
