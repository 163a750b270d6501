#include "app/viewer/scene_edits.h"

#include "gi/scene/scene_animation.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>
#include <string>

namespace lumina::app::viewer {

SceneEdits::SceneEdits(const scene::Scene& scene)
    : offsets_(scene.instances.size(), glm::vec3(0.0f)), yaws_(scene.instances.size(), 0.0f),
      emissionScales_(scene.materials.size(), 1.0f), playing_(!scene.animation.empty()) {
    for (const scene::Instance& instance : scene.instances) {
        restTransforms_.push_back(instance.transform);
        restCentres_.push_back(
            scene::transformBounds(scene.meshes.at(instance.mesh).bounds, instance.transform).centre());
    }
    for (const scene::Material& material : scene.materials) {
        restEmission_.push_back(material.emission);
    }
}

void SceneEdits::placeInstance(scene::Scene& scene, uint32_t instance, const glm::vec3& offset,
                               float yawDegrees) {
    offsets_.at(instance) = offset;
    yaws_.at(instance) = yawDegrees;
    const glm::vec3 centre = restCentres_[instance];
    const glm::mat4 turn =
        glm::translate(glm::mat4(1.0f), centre) *
        glm::rotate(glm::mat4(1.0f), glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
        glm::translate(glm::mat4(1.0f), -centre);
    scene.instances[instance].transform =
        glm::translate(glm::mat4(1.0f), offset) * turn * restTransforms_[instance];
}

void SceneEdits::animate(scene::Scene& scene) {
    if (playing_ && !scene.animation.empty()) {
        scene::animateScene(scene, animationFrame_++);
    }
}

bool SceneEdits::panels(scene::Scene& scene, float sceneDiagonal) {
    bool changed = false;
    if (!scene.instances.empty() && ImGui::CollapsingHeader("objects")) {
        const int last = int(scene.instances.size()) - 1;
        ImGui::SliderInt("instance", &selected_, 0, last);
        selected_ = std::clamp(selected_, 0, last);
        const auto i = uint32_t(selected_);
        ImGui::TextUnformatted(scene.instances[i].name.empty() ? "(unnamed)"
                                                               : scene.instances[i].name.c_str());
        glm::vec3 offset = offsets_[i];
        float yaw = yaws_[i];
        bool moved = ImGui::DragFloat3("offset", &offset.x, sceneDiagonal * 0.002f);
        moved |= ImGui::SliderFloat("turn about y", &yaw, -180.0f, 180.0f, "%.1f deg");
        if (ImGui::Button("back to rest")) {
            offset = glm::vec3(0.0f);
            yaw = 0.0f;
            moved = true;
        }
        if (moved) {
            placeInstance(scene, i, offset, yaw);
            changed = true;
        }
    }
    const bool anyEmissive = std::any_of(restEmission_.begin(), restEmission_.end(),
                                         [](const glm::vec3& e) { return e != glm::vec3(0.0f); });
    if (anyEmissive && ImGui::CollapsingHeader("emission")) {
        for (size_t m = 0; m < scene.materials.size(); ++m) {
            if (restEmission_[m] == glm::vec3(0.0f)) {
                continue;
            }
            ImGui::PushID(int(m));
            const std::string label =
                scene.materials[m].name.empty() ? "material " + std::to_string(m) : scene.materials[m].name;
            if (ImGui::SliderFloat(label.c_str(), &emissionScales_[m], 0.0f, 4.0f, "x %.2f")) {
                scene.materials[m].emission = restEmission_[m] * emissionScales_[m];
                changed = true;
            }
            ImGui::PopID();
        }
    }
    if (!scene.animation.empty() && ImGui::CollapsingHeader("animation", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("play", &playing_);
        ImGui::SameLine();
        if (ImGui::Button("restart")) {
            animationFrame_ = 0;
        }
        ImGui::Text("frame %llu (%.2f s of %.2f s)", static_cast<unsigned long long>(animationFrame_),
                    scene::animationTime(animationFrame_, scene.framesPerSecond), scene.animation.length());
    }
    return changed;
}

} // namespace lumina::app::viewer
