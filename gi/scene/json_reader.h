#pragma once
// Strict reading of a JSON object against the keys it may hold: an unknown key, a missing
// required key or a value of the wrong type is a SceneError naming the key, where it is
// ("camera", "lights[2]") and the file.
#include <filesystem>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lumina::scene {

class JsonObject {
public:
    // Checks that `value` is an object whose keys are all in `known`.
    JsonObject(const nlohmann::json& value, std::string where, const std::filesystem::path& file,
               std::initializer_list<std::string_view> known);

    bool has(std::string_view key) const { return value_.contains(key); }

    std::optional<double> number(std::string_view key) const;
    std::optional<std::string> string(std::string_view key) const;
    std::optional<bool> boolean(std::string_view key) const;
    std::optional<uint32_t> unsignedInt(std::string_view key, uint32_t min, uint32_t max) const;
    std::optional<glm::vec3> vec3(std::string_view key) const;
    const nlohmann::json* array(std::string_view key) const;
    const nlohmann::json* object(std::string_view key) const;

    // "camera.fovYDegrees" style path of a key, for messages.
    std::string path(std::string_view key) const;
    [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
    const std::filesystem::path& file() const { return file_; }

private:
    const nlohmann::json& value_;
    std::string where_;
    std::filesystem::path file_;
};

} // namespace lumina::scene
