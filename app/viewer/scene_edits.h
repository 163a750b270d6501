#pragma once
// What the viewer lets a user change in the scene while it runs (docs/viewer.md, "Scene edits"):
// objects moved and turned, emission made brighter or darker, the animation played or paused.
// The edits write the viewer's scene; every frame FrameRenderer::applyScene finds what changed
// and recomputes only that (docs/dynamic_scenes.md). Lights are edited by the lights panel.
#include "gi/scene/scene.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lumina::app::viewer {

class SceneEdits {
public:
    // Keeps the scene's rest pose: edits are made relative to it.
    explicit SceneEdits(const scene::Scene& scene);

    // The "objects", "emission" and "animation" panels; they edit `scene`. True when the scene
    // changed.
    bool panels(scene::Scene& scene, float sceneDiagonal);
    // Before each frame: the animation's pose for this frame when it plays (the objects panel's
    // edits of an animated instance are overridden by its tracks).
    void animate(scene::Scene& scene);
    // Moves instance `instance` by `offset` (world) and turns it `yawDegrees` about +y through its
    // rest box's centre; for scripted tests.
    void placeInstance(scene::Scene& scene, uint32_t instance, const glm::vec3& offset, float yawDegrees);

    bool playing() const { return playing_; }
    uint64_t animationFrame() const { return animationFrame_; }

private:
    std::vector<glm::mat4> restTransforms_;
    std::vector<glm::vec3> restCentres_; // world centres of the instances' rest boxes
    std::vector<glm::vec3> restEmission_;
    std::vector<glm::vec3> offsets_;
    std::vector<float> yaws_;
    std::vector<float> emissionScales_;
    int selected_ = 0;
    bool playing_ = false;
    uint64_t animationFrame_ = 0;
};

} // namespace lumina::app::viewer
