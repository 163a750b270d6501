#include "gi/scene/json_reader.h"

#include "gi/scene/scene_error.h"

#include <cmath>
#include <limits>

namespace lumina::scene {

namespace {

// Scene values end up in floats: a number beyond float's range is as wrong as a NaN.
bool isFloatNumber(const nlohmann::json& value) {
    return value.is_number() && std::isfinite(value.get<double>()) &&
           std::abs(value.get<double>()) <= double(std::numeric_limits<float>::max());
}

} // namespace

JsonObject::JsonObject(const nlohmann::json& value, std::string where, const std::filesystem::path& file,
                       std::initializer_list<std::string_view> known)
    : value_(value), where_(std::move(where)), file_(file) {
    if (!value_.is_object()) {
        throw SceneError(file_,
                         (where_.empty() ? std::string("the top level") : where_) + " must be a JSON object");
    }
    for (const auto& [key, _] : value_.items()) {
        bool found = false;
        for (std::string_view k : known) {
            found = found || k == key;
        }
        if (!found) {
            std::string list;
            for (std::string_view k : known) {
                list += (list.empty() ? "" : ", ") + std::string(k);
            }
            throw SceneError(file_, "unknown key '" + path(key) + "' (known keys" +
                                        (where_.empty() ? "" : " in " + where_) + ": " + list + ")");
        }
    }
}

std::string JsonObject::path(std::string_view key) const {
    return where_.empty() ? std::string(key) : where_ + "." + std::string(key);
}

void JsonObject::fail(std::string_view key, const std::string& problem) const {
    throw SceneError(file_, "'" + path(key) + "' " + problem);
}

std::optional<double> JsonObject::number(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return std::nullopt;
    }
    if (!isFloatNumber(*it)) {
        fail(key, "must be a finite number (within float range), not " + it->dump());
    }
    return it->get<double>();
}

std::optional<std::string> JsonObject::string(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return std::nullopt;
    }
    if (!it->is_string()) {
        fail(key, "must be a string, not " + it->dump());
    }
    return it->get<std::string>();
}

std::optional<bool> JsonObject::boolean(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return std::nullopt;
    }
    if (!it->is_boolean()) {
        fail(key, "must be true or false, not " + it->dump());
    }
    return it->get<bool>();
}

std::optional<uint32_t> JsonObject::unsignedInt(std::string_view key, uint32_t min, uint32_t max) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return std::nullopt;
    }
    if (!it->is_number_unsigned() || it->get<uint64_t>() < min || it->get<uint64_t>() > max) {
        fail(key, "must be a whole number in [" + std::to_string(min) + ", " + std::to_string(max) +
                      "], not " + it->dump());
    }
    return uint32_t(it->get<uint64_t>());
}

std::optional<glm::vec3> JsonObject::vec3(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return std::nullopt;
    }
    if (!it->is_array() || it->size() != 3) {
        fail(key, "must be an array of three numbers, not " + it->dump());
    }
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const nlohmann::json& v = (*it)[size_t(i)];
        if (!isFloatNumber(v)) {
            fail(key, "must be an array of three finite numbers, not " + it->dump());
        }
        out[i] = float(v.get<double>());
    }
    return out;
}

const nlohmann::json* JsonObject::array(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return nullptr;
    }
    if (!it->is_array()) {
        fail(key, "must be an array");
    }
    return &*it;
}

const nlohmann::json* JsonObject::object(std::string_view key) const {
    const auto it = value_.find(key);
    if (it == value_.end()) {
        return nullptr;
    }
    if (!it->is_object()) {
        fail(key, "must be a JSON object");
    }
    return &*it;
}

} // namespace lumina::scene
