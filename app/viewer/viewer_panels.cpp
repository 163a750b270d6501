// The viewer's UI (Dear ImGui): the frame full window (or the chosen debug view), and the
// panels: renderer (technique, preset, exposure, vsync), view (every intermediate buffer),
// lights (sun direction, each light's position, colour and intensity), objects, emission and the
// animation (scene_edits.h), GPU passes with their times and skip reasons, the frame-time graph
// and memory per subsystem.
#include "app/viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <numbers>
#include <vector>

namespace lumina::app::viewer {

namespace {

std::string megabytes(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

// The image fitted into the window, keeping its aspect ratio (letterboxed).
void drawFitted(ImTextureID texture, float imageWidth, float imageHeight) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float scale = std::min(display.x / imageWidth, display.y / imageHeight);
    const ImVec2 size(imageWidth * scale, imageHeight * scale);
    const ImVec2 origin((display.x - size.x) * 0.5f, (display.y - size.y) * 0.5f);
    ImGui::GetBackgroundDrawList()->AddImage(texture, origin, ImVec2(origin.x + size.x, origin.y + size.y));
}

bool combo(const char* label, std::string& value, const std::vector<std::string>& choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& choice : choices) {
            if (ImGui::Selectable(choice.c_str(), choice == value) && choice != value) {
                value = choice;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// A direction as azimuth (about y, degrees) and elevation (degrees above the horizon), the way
// a user thinks of the sun; `direction` is where the light travels, so the sun is at -direction.
bool sunDirection(glm::vec3& direction) {
    const glm::vec3 toSun = -glm::normalize(direction);
    float elevation = std::asin(std::clamp(toSun.y, -1.0f, 1.0f)) * 180.0f / std::numbers::pi_v<float>;
    float azimuth = std::atan2(toSun.x, toSun.z) * 180.0f / std::numbers::pi_v<float>;
    bool changed = ImGui::SliderFloat("azimuth", &azimuth, -180.0f, 180.0f, "%.1f deg");
    changed |= ImGui::SliderFloat("elevation", &elevation, -89.0f, 89.0f, "%.1f deg");
    if (changed) {
        const float a = azimuth * std::numbers::pi_v<float> / 180.0f;
        const float e = elevation * std::numbers::pi_v<float> / 180.0f;
        direction = -glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    }
    return changed;
}

} // namespace

// Where the slice views cut: the axis, the plane's world position within the scene's bounds, and
// for the SDF slice of a scene with cascades the cascade shown (auto: the finest holding the plane).
void Viewer::slicePanel(const BufferView& view) {
    SliceSettings& slice = state_.slice;
    static constexpr const char* kAxes[] = {"x", "y", "z"};
    int axis = int(slice.axis);
    if (ImGui::Combo("slice axis", &axis, kAxes, 3)) {
        slice.axis = uint32_t(axis);
        if (!sceneBounds_.empty()) {
            slice.position = 0.5f * (sceneBounds_.min[axis] + sceneBounds_.max[axis]);
        }
    }
    if (!sceneBounds_.empty()) {
        ImGui::SliderFloat("slice position", &slice.position, sceneBounds_.min[slice.axis],
                           sceneBounds_.max[slice.axis], "%.3f");
    }
    if (view.source != BufferView::Source::SdfSlice || renderer_->lumen() == nullptr) {
        return;
    }
    const sdf::SceneSdf& sdfs = renderer_->lumen()->sdf();
    const int count = int(sdfs.data().cascades.count);
    if (count > 1) {
        ImGui::SliderInt("cascade", &slice.cascade, -1, count - 1, slice.cascade < 0 ? "auto" : "%d");
    }
    const uint32_t shown = sliceCascade(sdfs, slice);
    const sdf::GlobalSdfSettings grid = sdfs.cascadeGrid(shown);
    ImGui::Text("cascade %u of %d: %ux%ux%u voxels of %.3g", shown, count, grid.dims.x, grid.dims.y,
                grid.dims.z, grid.voxelSize);
}

void Viewer::buildUi(const rhi::TextureHandle& image) {
    ImGui::NewFrame();
    drawFitted(ui_->texture(image), float(image->desc().width), float(image->desc().height));
    if (!state_.showUi) {
        ImGui::Render();
        return;
    }

    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("lumina-viewer");
    ImGui::Text("%s  %ux%u  %s", scene_.name.c_str(), scene_.image.width, scene_.image.height,
                device_.adapter().name.c_str());
    if (!state_.status.empty()) {
        ImGui::TextWrapped("%s", state_.status.c_str());
    }
    if (!state_.shaderError.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", state_.shaderError.c_str());
        ImGui::PopStyleColor();
    }
    if (ImGui::CollapsingHeader("renderer", ImGuiTreeNodeFlags_DefaultOpen)) {
        state_.rebuildRenderer |= combo("technique", state_.technique, gi::giTechniqueNames());
        if (state_.technique != "direct") {
            state_.rebuildRenderer |= combo("preset", state_.preset, gi::presetNames());
        }
        ImGui::SliderFloat("exposure (EV)", &state_.exposureEv, -8.0f, 8.0f, "%.1f");
        ImGui::Checkbox("vsync (V)", &state_.vsync);
        ImGui::Text("fly speed %.3g units/s (mouse wheel)", camera_.speed());
        state_.screenshotRequested |= ImGui::Button("screenshot (F12)");
    }
    if (ImGui::CollapsingHeader("view ([ and ])", ImGuiTreeNodeFlags_DefaultOpen)) {
        if (ImGui::BeginCombo("buffer", state_.views[state_.view].name.c_str())) {
            for (size_t i = 0; i < state_.views.size(); ++i) {
                if (ImGui::Selectable(state_.views[i].name.c_str(), i == state_.view)) {
                    state_.view = i;
                }
            }
            ImGui::EndCombo();
        }
        const BufferView& view = state_.views[state_.view];
        if (view.mode == LUMINA_VISUALISE_SCALAR || view.mode == LUMINA_VISUALISE_ALPHA) {
            ImGui::DragFloatRange2("range", &state_.views[state_.view].lo, &state_.views[state_.view].hi,
                                   std::max(1e-4f, (view.hi - view.lo) * 0.005f));
        }
        if (view.isSlice()) {
            slicePanel(view);
        }
    }
    if (ImGui::CollapsingHeader("lights")) {
        for (size_t i = 0; i < scene_.lights.size(); ++i) {
            scene::Light& light = scene_.lights[i];
            ImGui::PushID(int(i));
            const std::string title = std::to_string(i) + ": " + scene::lightTypeName(light.type) +
                                      (light.name.empty() ? "" : " " + light.name);
            if (ImGui::TreeNodeEx(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
                // The frame loop hands every edit of scene_ to the renderer (Viewer::applyEdits).
                ImGui::DragFloat("intensity", &light.intensity, std::max(light.intensity, 1e-3f) * 0.01f,
                                 0.0f, 1e9f, "%.4g");
                ImGui::ColorEdit3("colour", &light.color.x);
                if (light.type == scene::LightType::Directional) {
                    sunDirection(light.direction);
                } else {
                    ImGui::DragFloat3("position", &light.position.x, sceneDiagonal_ * 0.002f);
                }
                ImGui::TreePop();
            }
            ImGui::PopID();
        }
    }
    edits_.panels(scene_, sceneDiagonal_);
    if (ImGui::CollapsingHeader("frame time", ImGuiTreeNodeFlags_DefaultOpen)) {
        const std::vector<float> cpu(state_.frameMs.begin(), state_.frameMs.end());
        const std::vector<float> gpu(state_.gpuMs.begin(), state_.gpuMs.end());
        const float cpuLast = cpu.empty() ? 0.0f : cpu.back();
        const float gpuLast = gpu.empty() ? 0.0f : gpu.back();
        char overlay[64];
        std::snprintf(overlay, sizeof(overlay), "frame %.2f ms", cpuLast);
        ImGui::PlotLines("##frame", cpu.data(), int(cpu.size()), 0, overlay, 0.0f, FLT_MAX, ImVec2(0, 50));
        std::snprintf(overlay, sizeof(overlay), "GPU %.2f ms", gpuLast);
        ImGui::PlotLines("##gpu", gpu.data(), int(gpu.size()), 0, overlay, 0.0f, FLT_MAX, ImVec2(0, 50));
    }
    if (ImGui::CollapsingHeader("GPU passes")) {
        if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
            for (const rhi::TimerResult& timer : state_.timers) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(timer.name.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%.3f ms", timer.milliseconds);
            }
            for (const gi::SkippedPass& skip : state_.skipped) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", skip.pass.c_str());
                ImGui::TableNextColumn();
                ImGui::TextDisabled("skipped: %s", skip.reason.c_str());
            }
            ImGui::EndTable();
        }
    }
    if (ImGui::CollapsingHeader("memory")) {
        // Sampled from the device's allocation counter around each construction.
        ImGui::Text("scene (geometry, materials, textures)  %s", megabytes(memory_.scene).c_str());
        ImGui::Text("renderer (GBuffer, shadows, GI)        %s", megabytes(memory_.renderer).c_str());
        for (const gi::GiMemoryPart& part : memory_.gi) {
            ImGui::Text("  of which %-28s%s", part.name.c_str(), megabytes(part.bytes).c_str());
        }
        ImGui::Text("viewer (UI, swapchain copy)            %s", megabytes(memory_.viewer).c_str());
        ImGui::Text("device total now                       %s",
                    megabytes(device_.allocatedMemoryBytes()).c_str());
    }
    ImGui::End();
    ImGui::Render();
}

} // namespace lumina::app::viewer
