// A graphics pipeline drawing into three render targets (RGBA8, RGBA16F, R32F) with depth,
// checked pixel by pixel: overlapping quads must resolve by depth whatever the draw order,
// a back-facing quad must be culled, and the image must come out the right way up (clip-space
// y points up on every backend).
#include "shaders/rhi_tests/rhi_tests_shared.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/rhi/texel_patterns.h"

#include <cmath>
#include <cstring>
#include <numeric>

namespace lumina::test {
namespace {

using GraphicsTest = GpuTest;
using gpu::MrtPush;
using gpu::MrtVertex;

constexpr uint32_t kSize = 32;

// A screen-aligned rectangle in pixels (x right, y down from the top-left corner), with its
// edges on pixel boundaries so that coverage of every pixel centre is unambiguous.
struct PixelRect {
    uint32_t x0, y0, x1, y1;
    bool contains(uint32_t x, uint32_t y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

struct Quad {
    PixelRect rect;
    float depth;
    gpu::float4 color;
    float id;
};

// Two triangles, counter-clockwise as seen on screen (front-facing) unless `clockwise`.
std::vector<MrtVertex> quadVertices(const Quad& quad, bool clockwise) {
    const auto ndcX = [](uint32_t px) { return float(px) / (kSize / 2) - 1.0f; };
    const auto ndcY = [](uint32_t py) { return 1.0f - float(py) / (kSize / 2); }; // clip-space y up
    const gpu::float4 bottomLeft{ndcX(quad.rect.x0), ndcY(quad.rect.y1), quad.depth, 1};
    const gpu::float4 bottomRight{ndcX(quad.rect.x1), ndcY(quad.rect.y1), quad.depth, 1};
    const gpu::float4 topRight{ndcX(quad.rect.x1), ndcY(quad.rect.y0), quad.depth, 1};
    const gpu::float4 topLeft{ndcX(quad.rect.x0), ndcY(quad.rect.y0), quad.depth, 1};
    std::vector<gpu::float4> corners = {bottomLeft, bottomRight, topRight, bottomLeft, topRight, topLeft};
    if (clockwise) {
        std::swap(corners[1], corners[2]);
        std::swap(corners[4], corners[5]);
    }
    std::vector<MrtVertex> vertices;
    for (const gpu::float4& corner : corners) {
        vertices.push_back({corner, quad.color, {quad.id, 0, 0, 0}});
    }
    return vertices;
}

uint8_t toUnorm8(float value) {
    return static_cast<uint8_t>(std::lround(value * 255.0f));
}

TEST_P(GraphicsTest, MultipleRenderTargetsWithDepthArePixelExact) {
    LUMINA_REQUIRE_KERNELS();
    // Far quad A (drawn last), near quad B (drawn first), back-facing quad D (nearest of all,
    // must be culled). The colours are multiples of 1/255 so RGBA8 stores them exactly.
    const Quad far{{4, 4, 20, 20}, 0.5f, {1.0f, 0.0f, 0.2f, 1.0f}, 1.0f};
    const Quad near{{12, 12, 28, 28}, 0.25f, {0.0f, 1.0f, 0.6f, 0.2f}, 2.0f};
    const Quad culled{{0, 24, 32, 32}, 0.1f, {0.4f, 0.4f, 0.4f, 1.0f}, 3.0f};
    const MrtPush push{{2.0f, 0.5f, 4.0f, 1.0f}};

    // Vertices 0-5: B, drawn with draw(). 6-11: A, 12-17: D, drawn indexed.
    std::vector<MrtVertex> vertices = quadVertices(near, false);
    for (const auto& [quad, clockwise] : {std::pair{far, false}, std::pair{culled, true}}) {
        const auto more = quadVertices(quad, clockwise);
        vertices.insert(vertices.end(), more.begin(), more.end());
    }
    std::vector<uint16_t> indices(12);
    std::iota(indices.begin(), indices.end(), uint16_t(6));

    rhi::BufferHandle vertexBuffer =
        rhi::createBufferWithData(device(),
                                  {.structStride = sizeof(MrtVertex),
                                   .usage = rhi::BufferUsage::Structured,
                                   .debugName = "mrt vertices"},
                                  vertices.data(), vertices.size() * sizeof(MrtVertex));
    rhi::BufferHandle indexBuffer =
        rhi::createBufferWithData(device(), {.usage = rhi::BufferUsage::Index, .debugName = "mrt indices"},
                                  indices.data(), indices.size() * 2);
    rhi::BufferHandle unrelated = device().createBuffer({.size = 64, .debugName = "splits the render pass"});

    const auto target = [&](rhi::Format format, const char* name) {
        return device().createTexture({.format = format,
                                       .width = kSize,
                                       .height = kSize,
                                       .usage = rhi::TextureUsage::RenderTarget | rhi::TextureUsage::Sampled,
                                       .debugName = name});
    };
    rhi::TextureHandle color8 = target(rhi::Format::RGBA8_UNORM, "target rgba8");
    rhi::TextureHandle color16 = target(rhi::Format::RGBA16_FLOAT, "target rgba16f");
    rhi::TextureHandle ids = target(rhi::Format::R32_FLOAT, "target r32f");
    rhi::TextureHandle depth = device().createTexture({.format = rhi::Format::D32_FLOAT,
                                                       .width = kSize,
                                                       .height = kSize,
                                                       .usage = rhi::TextureUsage::DepthStencil,
                                                       .debugName = "depth"});

    rhi::BindingLayoutHandle layout =
        device().createBindingLayout({.space = 0,
                                      .visibility = rhi::ShaderStageMask::Vertex,
                                      .items = {{rhi::BindingType::BufferSRV, 0}}});
    rhi::GraphicsPipelineHandle pipeline = device().createGraphicsPipeline(
        {.vertexShader = shaders().get("rhi_tests/mrt.vsMain", rhi::ShaderStage::Vertex),
         .pixelShader = shaders().get("rhi_tests/mrt.psMain", rhi::ShaderStage::Pixel),
         .layouts = {layout},
         .pushConstantBytes = sizeof(MrtPush),
         .raster = {.cullMode = rhi::CullMode::Back, .frontCounterClockwise = true},
         .depth = {.testEnable = true, .writeEnable = true, .compareOp = rhi::CompareOp::Less},
         .colorFormats = {rhi::Format::RGBA8_UNORM, rhi::Format::RGBA16_FLOAT, rhi::Format::R32_FLOAT},
         .blend = {},
         .depthFormat = rhi::Format::D32_FLOAT,
         .debugName = "mrt"});

    const std::array<float, 4> background8{0, 0, 0, 0}, background16{0.25f, 0.25f, 0.25f, 0.25f},
        backgroundId{-1, 0, 0, 0};
    rhi::CommandListHandle list = device().createCommandList();
    list->begin();
    list->clearColor(*color8, background8);
    list->clearColor(*color16, background16);
    list->clearColor(*ids, backgroundId);
    list->clearDepth(*depth, 1.0f);
    list->setGraphicsState({.pipeline = pipeline,
                            .colorAttachments = {{color8}, {color16}, {ids}},
                            .depthAttachment = rhi::Attachment{depth},
                            .bindings = {{layout, {rhi::BindingSetItem::structuredBuffer(0, vertexBuffer)}}},
                            .viewport = {}, // the whole target
                            .scissor = {},
                            .indexBuffer = rhi::IndexBufferBinding{indexBuffer, rhi::IndexFormat::Uint16}});
    list->pushConstants(push);
    list->draw({.vertexOrIndexCount = 6});
    list->fillBuffer(*unrelated, 0); // ends the render pass; the next draw must load, not clear
    list->drawIndexed({.vertexOrIndexCount = 6, .firstVertexOrIndex = 0});
    list->drawIndexed({.vertexOrIndexCount = 6, .firstVertexOrIndex = 6});
    list->end();
    submitAndWait(*list);

    const std::vector<uint8_t> pixels8 = rhi::readTexture(device(), *color8);
    const std::vector<uint8_t> pixels16 = rhi::readTexture(device(), *color16);
    const std::vector<uint8_t> pixelsId = rhi::readTexture(device(), *ids);
    const std::vector<uint8_t> pixelsDepth = rhi::readTexture(device(), *depth);
    const auto* halves = reinterpret_cast<const uint16_t*>(pixels16.data());
    const auto* idValues = reinterpret_cast<const float*>(pixelsId.data());
    const auto* depthValues = reinterpret_cast<const float*>(pixelsDepth.data());
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const Quad* visible = near.rect.contains(x, y) ? &near : far.rect.contains(x, y) ? &far : nullptr;
            const size_t pixel = size_t(y) * kSize + x;
            const std::string where =
                "pixel " + std::to_string(x) + "," + std::to_string(y) + " (" +
                (visible ? "quad id " + std::to_string(int(visible->id)) : "background") + ")";
            for (int c = 0; c < 4; ++c) {
                const float color = visible ? visible->color[c] : background8[c];
                ASSERT_EQ(pixels8[pixel * 4 + c], toUnorm8(color)) << where << " rgba8 channel " << c;
                const float scaled = visible ? visible->color[c] * push.tint[c] : background16[c];
                // Half floats hold 11 significant bits.
                ASSERT_NEAR(halfToFloat(halves[pixel * 4 + c]), scaled, std::abs(scaled) * 1e-3f)
                    << where << " rgba16f channel " << c;
            }
            ASSERT_EQ(idValues[pixel], visible ? visible->id : backgroundId[0]) << where << " r32f";
            ASSERT_NEAR(depthValues[pixel], visible ? visible->depth : 1.0f, 1e-6f) << where << " depth";
        }
    }
}

LUMINA_INSTANTIATE_GPU_TEST(GraphicsTest);

} // namespace
} // namespace lumina::test
