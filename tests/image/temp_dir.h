#pragma once
// A fresh directory per test under the system temp folder, removed afterwards.
#include <filesystem>
#include <gtest/gtest.h>
#include <random>
#include <string>

namespace lumina::testing {

class TempDir : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::random_device random;
        dir_ = std::filesystem::temp_directory_path() / ("lumina_" + std::string(info->test_suite_name()) +
                                                         "_" + info->name() + "_" + std::to_string(random()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    std::filesystem::path path(const std::string& name) const { return dir_ / name; }

private:
    std::filesystem::path dir_;
};

} // namespace lumina::testing
