#pragma once
// Every problem with a scene's input (a glTF, a scene file, a generator's parameters) is a
// SceneError that names the file and says what was wrong, so a user can fix the file.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace lumina::scene {

class SceneError : public std::runtime_error {
public:
    SceneError(const std::filesystem::path& file, const std::string& problem)
        : std::runtime_error(file.empty() ? problem : file.generic_string() + ": " + problem), file_(file),
          problem_(problem) {}

    const std::filesystem::path& file() const { return file_; }
    const std::string& problem() const { return problem_; }

private:
    std::filesystem::path file_;
    std::string problem_;
};

} // namespace lumina::scene
