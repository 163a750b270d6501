// The GPU card BVH traversal (shaders/surface_cache/card_bvh_traversal.hlsli, through the test
// kernel card_bvh_query_test.hlsl) against the CPU query and brute force, on random cards and on
// the Cornell box's cards.
#include "gi/scene/scene_loader.h"
#include "gi/surface_cache/card_bvh.h"
#include "gi/surface_cache/surface_cards.h"
#include "shaders/common/constants_shared.h"
#include "shaders/surface_cache/card_bvh_test_shared.h"
#include "tests/rhi/gpu_test_fixture.h"
#include "tests/surface_cache/random_cards.h"
#include "tests/surface_cache/scene_triangles.h"

namespace lumina::test {
namespace {

using namespace lumina::surface_cache;

constexpr uint32_t kGroupSize = LUMINA_LINEAR_GROUP_SIZE; // numthreads of card_bvh_query_test

class SurfaceCacheCardBvhGpu : public GpuTest {
protected:
    // Runs every query on the GPU and checks it against the CPU; returns how many found a card.
    uint32_t checkQueries(const std::vector<gpu::SurfaceCard>& cards,
                          const std::vector<surface_cache::test::OwnerQuery>& queries) {
        const CardBvh bvh = buildCardBvh(cards);
        EXPECT_LE(bvh.depth, LUMINA_CARD_BVH_STACK_SIZE);
        std::vector<gpu::CardBvhQuery> gpuQueries;
        for (const surface_cache::test::OwnerQuery& q : queries) {
            gpuQueries.push_back({glm::vec4(q.position, gpu::asfloat(q.instance)), glm::vec4(q.normal, 0.0f),
                                  glm::vec4(q.seenFrom, 0.0f)});
        }
        auto structured = [&](const void* data, size_t count, size_t stride, const char* name) {
            return rhi::createBufferWithData(device(),
                                             {.size = count * stride,
                                              .structStride = uint32_t(stride),
                                              .usage = rhi::BufferUsage::Structured,
                                              .debugName = name},
                                             data, count * stride);
        };
        // A buffer may not be empty: with no cards, one card that no traversal reaches.
        const std::vector<gpu::SurfaceCard> cardData =
            cards.empty() ? std::vector<gpu::SurfaceCard>(1) : cards;
        rhi::BufferHandle nodeBuffer =
            structured(bvh.nodes.data(), bvh.nodes.size(), sizeof(gpu::CardBvhNode), "card bvh nodes");
        rhi::BufferHandle cardBuffer =
            structured(cardData.data(), cardData.size(), sizeof(gpu::SurfaceCard), "surface cards");
        rhi::BufferHandle queryBuffer =
            structured(gpuQueries.data(), gpuQueries.size(), sizeof(gpu::CardBvhQuery), "card queries");
        const uint32_t count = uint32_t(queries.size());
        rhi::BufferHandle results =
            device().createBuffer({.size = count * sizeof(gpu::CardBvhQueryResult),
                                   .structStride = sizeof(gpu::CardBvhQueryResult),
                                   .usage = rhi::BufferUsage::Structured | rhi::BufferUsage::Storage,
                                   .debugName = "card owners"});
        const ComputeKernel kernel = loadComputeKernel("surface_cache/card_bvh_query_test",
                                                       {{rhi::BindingType::BufferSRV, 0},
                                                        {rhi::BindingType::BufferSRV, 1},
                                                        {rhi::BindingType::BufferSRV, 2},
                                                        {rhi::BindingType::BufferUAV, 0}},
                                                       sizeof(gpu::CardBvhQueryConstants));
        rhi::CommandListHandle list = device().createCommandList();
        list->begin();
        list->setComputeState({.pipeline = kernel.pipeline,
                               .bindings = {{kernel.layout,
                                             {rhi::BindingSetItem::structuredBuffer(0, nodeBuffer),
                                              rhi::BindingSetItem::structuredBuffer(1, cardBuffer),
                                              rhi::BindingSetItem::structuredBuffer(2, queryBuffer),
                                              rhi::BindingSetItem::rwStructuredBuffer(0, results)}}}});
        list->pushConstants(gpu::CardBvhQueryConstants{count, 0, 0, 0});
        list->dispatch((count + kGroupSize - 1) / kGroupSize);
        list->end();
        submitAndWait(*list);

        const std::vector<gpu::CardBvhQueryResult> gpuResults = readBack<gpu::CardBvhQueryResult>(*results);
        EXPECT_EQ(gpuResults.size(), count);
        uint32_t found = 0, nearTies = 0;
        for (uint32_t i = 0; i < count && i < gpuResults.size(); ++i) {
            const surface_cache::test::OwnerQuery& q = queries[i];
            const CardOwner cpu = findCardOwner(bvh, cards, q.position, q.normal, q.instance, q.seenFrom);
            EXPECT_EQ(cpu.card,
                      findCardOwnerBruteForce(cards, q.position, q.normal, q.instance, q.seenFrom).card);
            const uint32_t gpuCard = gpu::asuint(gpuResults[i].ownerAndScore.x);
            const float gpuScore = gpuResults[i].ownerAndScore.y;
            found += cpu.card != LUMINA_NO_CARD;
            if (gpuCard == cpu.card) {
                if (cpu.card != LUMINA_NO_CARD) {
                    EXPECT_NEAR(gpuScore, cpu.score, 1e-5f) << "query " << i;
                }
                continue;
            }
            // Candidates are decided without arithmetic, so both saw the same cards; the GPU may
            // round a score differently (fused multiply-add) and so pick the other of two cards
            // whose scores are within rounding of each other. Nothing else is allowed.
            const bool bothFound = cpu.card != LUMINA_NO_CARD && gpuCard < cards.size();
            EXPECT_TRUE(bothFound) << "query " << i << ": cpu " << cpu.card << ", gpu " << gpuCard;
            if (!bothFound) {
                continue;
            }
            const gpu::SurfaceCard& other = cards[gpuCard];
            EXPECT_TRUE(gpu::cardContains(other, q.position) && gpu::cardFacesRay(other, q.seenFrom))
                << "query " << i;
            EXPECT_NEAR(gpu::cardOwnerScoreOnInstance(other, q.position, q.normal, q.instance), cpu.score,
                        1e-5f)
                << "query " << i;
            ++nearTies;
        }
        EXPECT_LE(nearTies, count / 1000) << "too many near-ties to be rounding";
        return found;
    }
};

TEST_P(SurfaceCacheCardBvhGpu, RandomCardsMatchTheCpu) {
    LUMINA_REQUIRE_KERNELS();
    for (uint32_t cardCount : {0u, 3u, 700u, 5000u}) {
        SCOPED_TRACE(cardCount);
        const std::vector<gpu::SurfaceCard> cards =
            surface_cache::test::randomCards(cardCount, 7 + cardCount);
        const uint32_t found =
            checkQueries(cards, surface_cache::test::randomQueries(cards, 8192, 3 * cardCount + 1));
        if (cardCount >= 700) {
            // Most queries lie near cards, a third of them with a ray that skips the back-facing
            // ones: owners were exercised.
            EXPECT_GT(found, 3000u);
        } else if (cardCount == 0) {
            EXPECT_EQ(found, 0u);
        }
    }
}

TEST_P(SurfaceCacheCardBvhGpu, CornellBoxHitsFindTheirCards) {
    LUMINA_REQUIRE_KERNELS();
    const scene::Scene scene = scene::loadScene("cornell_box");
    const SurfaceCards cards(scene);
    // Points on every triangle with its normal, and a grid through the box with axis normals.
    std::vector<surface_cache::test::OwnerQuery> queries;
    for (const surface_cache::test::WorldTriangle& tri : surface_cache::test::worldTriangles(scene)) {
        const glm::vec3 a = tri.a, b = tri.b, c = tri.c, n = tri.normal;
        for (float s : {0.1f, 0.33f, 0.6f}) {
            queries.push_back({a + s * (b - a) + 0.5f * (1.0f - s) * (c - a), n});
        }
    }
    for (int i = 0; i < 4096; ++i) {
        glm::vec3 n(0.0f);
        n[i % 3] = (i / 3) % 2 ? 1.0f : -1.0f;
        const glm::vec3 p(float((i * 37) % 560), float((i * 53) % 550), float((i * 91) % 560));
        queries.push_back({p, n});
    }
    const uint32_t found = checkQueries(cards.cards(), queries);
    EXPECT_GE(found, uint32_t(queries.size() - 4096));
}

LUMINA_INSTANTIATE_GPU_TEST(SurfaceCacheCardBvhGpu);

} // namespace
} // namespace lumina::test
