#pragma once
// The GoogleTest side of goldens (docs/goldens.md): a list of (spec, image) checked in one go,
// each result printed and every failure reported with its message; and the name of a test
// parameterised by backend and scene.
//
//   expectGoldensMatch({{spec(name, "albedo", kUnitRange), albedo}, ...}, device().adapter());
//   INSTANTIATE_TEST_SUITE_P(Scenes, MyGoldenTest, ::testing::Combine(apis, scenes), backendSceneName);
#include "rhi/rhi.h"
#include "tests/golden/golden.h"

#include <gtest/gtest.h>
#include <iostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace lumina::test {

using GoldenChecks = std::vector<std::pair<GoldenSpec, image::Image>>;

inline void expectGoldensMatch(const GoldenChecks& checks, const rhi::AdapterInfo& adapter) {
    for (const auto& [golden, image] : checks) {
        const GoldenResult result = checkGolden(golden, image, adapter);
        EXPECT_TRUE(result.passed) << result.message;
        std::cout << result.message << '\n';
    }
}

// "vulkan_cornell_box" for the parameters (vulkan, "cornell_box").
inline std::string backendSceneName(const ::testing::TestParamInfo<std::tuple<rhi::Api, std::string>>& info) {
    return std::string(rhi::apiName(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
}

} // namespace lumina::test
