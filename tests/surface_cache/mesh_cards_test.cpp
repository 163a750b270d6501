// Cards of a mesh (mesh_cards.h) and their placement by an instance (card_placement.h).
#include "gi/scene/mesh_builder.h"
#include "gi/surface_cache/card_placement.h"
#include "gi/surface_cache/mesh_cards.h"
#include "shaders/surface_cache/card_bvh_shared.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <set>

namespace lumina::surface_cache {
namespace {

using scene::Material;
using scene::Mesh;
using scene::MeshBuilder;

const std::vector<Material> kOneSided = {Material{.name = "one-sided"}};
const std::vector<Material> kTwoSided = {Material{.name = "two-sided", .doubleSided = true}};

Mesh boxMesh(glm::vec3 lo, glm::vec3 hi) {
    MeshBuilder b("box");
    b.box(lo, hi);
    return b.finish();
}

// A quad facing +y at height y over [x0, x1] x [z0, z1].
void upQuad(MeshBuilder& b, float y, float x0, float x1, float z0, float z1) {
    b.quad({x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0});
}

TEST(SurfaceCacheMeshCards, ClosedBoxGetsSixCardsOnItsFaces) {
    const Mesh mesh = boxMesh({-1, -2, -3}, {1, 2, 3});
    const std::vector<MeshCard> cards = buildMeshCards(mesh, kOneSided, {});
    ASSERT_EQ(cards.size(), 6u);
    for (uint32_t axis = 0; axis < 6; ++axis) {
        const MeshCard& card = cards[axis];
        EXPECT_EQ(card.axis, axis);
        EXPECT_EQ(card.triangleCount, 2u);
        EXPECT_FALSE(card.twoSided);
        // The card's box is its face: flat along its axis, at the side it looks from.
        const uint32_t a = axis / 2;
        EXPECT_EQ(card.bounds.size()[a], 0.0f);
        EXPECT_EQ(card.bounds.min[a], axis % 2 == 0 ? mesh.bounds.max[a] : mesh.bounds.min[a]);
        const glm::vec3 size = mesh.bounds.size();
        EXPECT_FLOAT_EQ(card.projectedArea, size[(a + 1) % 3] * size[(a + 2) % 3]);
    }
}

TEST(SurfaceCacheMeshCards, AxesAreRightHanded) {
    for (uint32_t axis = 0; axis < 6; ++axis) {
        const CardAxes axes = cardAxes(axis);
        EXPECT_EQ(glm::cross(axes.u, axes.v), axes.normal) << axis;
    }
    EXPECT_THROW(cardAxes(6), std::invalid_argument);
}

TEST(SurfaceCacheMeshCards, OneSidedQuadGetsOneCardAndTwoSidedGetsTwo) {
    MeshBuilder b("quad");
    upQuad(b, 0.0f, 0, 4, 0, 2);
    const Mesh quad = b.finish();
    const std::vector<MeshCard> one = buildMeshCards(quad, kOneSided, {});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].axis, LUMINA_CARD_AXIS_POS_Y);
    const std::vector<MeshCard> two = buildMeshCards(quad, kTwoSided, {});
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].axis, LUMINA_CARD_AXIS_POS_Y);
    EXPECT_FALSE(two[0].twoSided);
    EXPECT_EQ(two[1].axis, LUMINA_CARD_AXIS_NEG_Y);
    EXPECT_TRUE(two[1].twoSided);
}

TEST(SurfaceCacheMeshCards, HiddenLayersGetTheirOwnCardsAndSideBySideLayersShareOne) {
    MeshBuilder shelf("shelf");
    upQuad(shelf, 2.0f, 0, 4, 0, 1); // the upper board hides the lower one from +y
    upQuad(shelf, 0.0f, 0, 4, 0, 1);
    const std::vector<MeshCard> shelfCards = buildMeshCards(shelf.finish(), kOneSided, {});
    ASSERT_EQ(shelfCards.size(), 2u);
    EXPECT_EQ(shelfCards[0].bounds.min.y, 2.0f); // front (upper) first
    EXPECT_EQ(shelfCards[1].bounds.max.y, 0.0f);

    MeshBuilder stairs("stairs");
    for (int step = 0; step < 4; ++step) {
        upQuad(stairs, float(step), float(step), float(step + 1), 0, 1); // no step over another
    }
    const std::vector<MeshCard> stairCards = buildMeshCards(stairs.finish(), kOneSided, {});
    ASSERT_EQ(stairCards.size(), 1u);
    EXPECT_EQ(stairCards[0].triangleCount, 8u);

    MeshBuilder tower("tower");
    for (int level = 0; level < 7; ++level) {
        upQuad(tower, float(3 * level), 0, 1, 0, 1); // seven boards over each other
    }
    SurfaceCacheSettings settings;
    settings.maxCardsPerAxis = 3;
    const std::vector<MeshCard> towerCards = buildMeshCards(tower.finish(), kOneSided, settings);
    ASSERT_EQ(towerCards.size(), 3u);
    EXPECT_EQ(towerCards[2].triangleCount, 10u); // the five deepest share the last card
}

TEST(SurfaceCacheMeshCards, ZeroSizeAndBrokenMeshesThrowNamingTheMesh) {
    Mesh empty;
    empty.name = "nothing";
    EXPECT_THROW(buildMeshCards(empty, kOneSided, {}), std::invalid_argument);
    Mesh point;
    point.name = "a point";
    point.positions = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
    point.indices = {0, 1, 2, 0, 2, 1};
    try {
        buildMeshCards(point, kOneSided, {});
        FAIL() << "a zero-size mesh got cards";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'a point' has zero size"), std::string::npos) << e.what();
    }
    Mesh broken = point;
    broken.indices = {0, 1, 7};
    EXPECT_THROW(buildMeshCards(broken, kOneSided, {}), std::invalid_argument);
    SurfaceCacheSettings bad;
    bad.texelsPerUnit = 0.0f;
    EXPECT_THROW(buildMeshCards(boxMesh({0, 0, 0}, {1, 1, 1}), kOneSided, bad), std::invalid_argument);
}

TEST(SurfaceCachePlacement, WorldToCardMapsTheSurfaceIntoTheUnitCube) {
    const Mesh mesh = boxMesh({-1, -2, -3}, {1, 2, 3});
    const std::vector<MeshCard> cards = buildMeshCards(mesh, kOneSided, {});
    // Rotated, non-uniformly scaled and moved; and mirrored, which flips the winding.
    glm::mat4 transform = glm::translate(glm::mat4(1.0f), {10, -5, 2}) *
                          glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 0.5f))) *
                          glm::scale(glm::mat4(1.0f), {2.0f, 0.5f, 3.0f});
    for (const glm::mat4& m : {transform, transform * glm::scale(glm::mat4(1.0f), {-1.0f, 1.0f, 1.0f})}) {
        SurfaceCacheSettings settings;
        settings.texelsPerUnit = 40.0f;
        for (const MeshCard& meshCard : cards) {
            const PlacedCard placed = placeCard(meshCard, m, settings);
            const gpu::SurfaceCard& card = placed.card;
            const CardAxes axes = cardAxes(meshCard.axis);
            // Corners of the card's face map to (u, v) in [0, 1] and to the middle of the depth slab.
            glm::vec2 uvMin(1e9f), uvMax(-1e9f);
            for (uint32_t c = 0; c < 8; ++c) {
                const glm::vec3 corner((c & 1u) ? meshCard.bounds.max.x : meshCard.bounds.min.x,
                                       (c & 2u) ? meshCard.bounds.max.y : meshCard.bounds.min.y,
                                       (c & 4u) ? meshCard.bounds.max.z : meshCard.bounds.min.z);
                const glm::vec3 world(m * glm::vec4(corner, 1.0f));
                const glm::vec3 local = gpu::worldToCardSpace(card, world);
                uvMin = glm::min(uvMin, glm::vec2(local));
                uvMax = glm::max(uvMax, glm::vec2(local));
                EXPECT_NEAR(local.z, 0.5f, 1e-3f);
                // Inside the padded world bounds.
                EXPECT_TRUE(gpu::cardContains(card, world));
            }
            EXPECT_NEAR(uvMin.x, 0.0f, 1e-4f);
            EXPECT_NEAR(uvMin.y, 0.0f, 1e-4f);
            EXPECT_NEAR(uvMax.x, 1.0f, 1e-4f);
            EXPECT_NEAR(uvMax.y, 1.0f, 1e-4f);
            // Moving along the world normal towards the front lowers z.
            const glm::vec3 centre(m * glm::vec4(meshCard.bounds.centre(), 1.0f));
            const glm::vec3 normal(card.normalAndPadding);
            EXPECT_LT(gpu::worldToCardSpace(card, centre + 0.01f * normal).z,
                      gpu::worldToCardSpace(card, centre).z);
            EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
            // The world normal is the transformed face normal.
            const glm::vec3 expected =
                glm::normalize(glm::transpose(glm::inverse(glm::mat3(m))) * axes.normal);
            EXPECT_NEAR(glm::dot(normal, expected), 1.0f, 1e-5f);
            // Tiles from the world size: side length x scale x texels per unit, rounded up.
            const float worldU =
                glm::length(glm::mat3(m) * axes.u) * glm::dot(meshCard.bounds.size(), glm::abs(axes.u));
            EXPECT_EQ(placed.tilesX, uint32_t(std::ceil(worldU * 40.0f / float(kTileSize))));
            EXPECT_EQ(card.normalAndPadding.w, paddingUnits(settings));
        }
    }
}

TEST(SurfaceCachePlacement, SingularTransformThrows) {
    const std::vector<MeshCard> cards = buildMeshCards(boxMesh({0, 0, 0}, {1, 1, 1}), kOneSided, {});
    EXPECT_THROW(placeCard(cards[0], glm::scale(glm::mat4(1.0f), {1.0f, 0.0f, 1.0f}), {}),
                 std::invalid_argument);
}

TEST(SurfaceCachePlacement, TilesAreCappedAndAtLeastOne) {
    const std::vector<MeshCard> cards = buildMeshCards(boxMesh({0, 0, 0}, {1000, 0.001f, 1}), kOneSided, {});
    SurfaceCacheSettings settings;
    settings.maxCardTexels = 8 * kTileSize;
    for (const MeshCard& card : cards) {
        const PlacedCard placed = placeCard(card, glm::mat4(1.0f), settings);
        EXPECT_GE(placed.tilesX, 1u);
        EXPECT_GE(placed.tilesY, 1u);
        EXPECT_LE(placed.tilesX, 8u);
        EXPECT_LE(placed.tilesY, 8u);
    }
    // A small atlas caps cards at its own side.
    settings.atlasSize = 4 * kTileSize;
    EXPECT_EQ(maxCardTilesIn(settings), 4u);
    ASSERT_EQ(cards[4].axis, LUMINA_CARD_AXIS_POS_Z); // u along x: 1000 units
    EXPECT_EQ(placeCard(cards[4], glm::mat4(1.0f), settings).tilesX, 4u);
}

} // namespace
} // namespace lumina::surface_cache
