// The pipeline-creation check of a pass's registers against its kernel's SPIR-V, on kernels the
// build made (no device needed): the right bindings pass, a register off by one or a resource of
// the wrong kind is an error naming the kernel's variable, its register and what the pass bound.
#include "gi/core/kernel_bindings.h"
#include "rhi/rhi.h"
#include "rhi/shader_library.h"

#include <gtest/gtest.h>

namespace lumina::gi {
namespace {

using rhi::BindingSetItem;

std::vector<KernelResource> resourcesOf(std::string_view kernel) {
    const std::vector<uint32_t> spirv = readKernelSpirv(rhi::defaultShaderDirectory().string(), kernel);
    EXPECT_FALSE(spirv.empty()) << "no SPIR-V for " << kernel << " in " << rhi::defaultShaderDirectory();
    return kernelResources(kernel, spirv);
}

std::string errorOf(std::string_view kernel, const SpaceBindings& bindings) {
    try {
        checkKernelBindings(kernel, resourcesOf(kernel), bindings);
    } catch (const rhi::Error& e) {
        return e.what();
    }
    return {};
}

// screen_probes/probe_brdf_pdf: ConstantBuffer gSp (b1), StructuredBuffer gProbes (t0),
// RWStructuredBuffer gBrdfPdf (u0).
constexpr const char* kKernel = "screen_probes/probe_brdf_pdf";

TEST(KernelBindings, ReadsRegistersAndKindsFromSpirv) {
    const std::vector<KernelResource> resources = resourcesOf(kKernel);
    ASSERT_EQ(resources.size(), 3u);
    bool constants = false, probes = false, pdf = false;
    for (const KernelResource& r : resources) {
        constants |= r.name == "gSp" && r.registerClass == 'b' && r.reg == 1 &&
                     r.kind == KernelResourceKind::ConstantBuffer;
        probes |= r.name == "gProbes" && r.registerClass == 't' && r.reg == 0 &&
                  r.kind == KernelResourceKind::Buffer;
        pdf |= r.name == "gBrdfPdf" && r.registerClass == 'u' && r.reg == 0 &&
               r.kind == KernelResourceKind::Buffer;
    }
    EXPECT_TRUE(constants && probes && pdf);
}

TEST(KernelBindings, MatchingBindingsPass) {
    const SpaceBindings bindings = {{BindingSetItem::constantBuffer(1, nullptr),
                                     BindingSetItem::structuredBuffer(0, nullptr),
                                     BindingSetItem::rwStructuredBuffer(0, nullptr)}};
    EXPECT_EQ(errorOf(kKernel, bindings), "");
}

TEST(KernelBindings, ExtraBindingsAreAllowed) {
    const SpaceBindings bindings = {
        {BindingSetItem::constantBuffer(1, nullptr), BindingSetItem::structuredBuffer(0, nullptr),
         BindingSetItem::structuredBuffer(7, nullptr), BindingSetItem::rwStructuredBuffer(0, nullptr)}};
    EXPECT_EQ(errorOf(kKernel, bindings), "");
}

TEST(KernelBindings, AMissingRegisterNamesBothSides) {
    const SpaceBindings bindings = {{BindingSetItem::constantBuffer(1, nullptr),
                                     BindingSetItem::structuredBuffer(1, nullptr), // the kernel reads t0
                                     BindingSetItem::rwStructuredBuffer(0, nullptr)}};
    const std::string error = errorOf(kKernel, bindings);
    EXPECT_NE(error.find("kernel 'screen_probes/probe_brdf_pdf' uses gProbes at register(t0)"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("binds nothing there (it binds b1, t1, u0"), std::string::npos) << error;
}

TEST(KernelBindings, AWrongKindNamesBothSides) {
    const SpaceBindings bindings = {{BindingSetItem::constantBuffer(1, nullptr),
                                     BindingSetItem::sampledTexture(0, nullptr), // a texture at t0
                                     BindingSetItem::rwStructuredBuffer(0, nullptr)}};
    const std::string error = errorOf(kKernel, bindings);
    EXPECT_NE(error.find("gProbes at register(t0), which is a buffer, but the pass binds a texture"),
              std::string::npos)
        << error;
}

TEST(KernelBindings, MalformedSpirvIsAnError) {
    const std::vector<uint32_t> words = {0x07230203u, 0x00010300u, 0u, 10u, 0u, (9u << 16) | 59u};
    EXPECT_THROW(kernelResources("bad", words), rhi::Error);
    EXPECT_THROW(kernelResources("bad", std::vector<uint32_t>{1u, 2u}), rhi::Error);
}

} // namespace
} // namespace lumina::gi
