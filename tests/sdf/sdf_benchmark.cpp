// Build times of mesh SDFs (64^3, the default) and of BVHs. Not a test: prints figures.
//   sdf_benchmark [--benchmark_filter=...]
#include "gi/sdf/mesh_sdf.h"
#include "tests/bvh/test_meshes.h"

#include <benchmark/benchmark.h>

namespace lumina {
namespace {

test::Mesh benchMesh(int kind) {
    switch (kind) {
    case 0:
        return test::makeBox({-1.0f, -0.5f, -0.3f}, {1.0f, 0.5f, 0.3f}, 8); // 768 triangles
    case 1:
        return test::makeIcosphere({0, 0, 0}, 1.0f, 4); // 5120 triangles
    default: {
        test::Mesh mesh = test::makeIcosphere({0, 0, 0}, 1.0f, 6); // 81920 + 2 x 5120 triangles
        mesh.append(test::makeIcosphere({1.2f, 0.3f, 0}, 0.5f, 4));
        mesh.append(test::makeBox({-2.0f, -1.2f, -2.0f}, {2.0f, -1.0f, 2.0f}, 16));
        return mesh;
    }
    }
}

void meshSdfBuild(benchmark::State& state) {
    const test::Mesh mesh = benchMesh(int(state.range(0)));
    sdf::SdfSettings settings; // 64 voxels along the longest axis
    double seconds = 0.0;
    for (auto _ : state) {
        const sdf::MeshSdf sdf = sdf::buildMeshSdf(mesh.positions, mesh.indices, settings);
        seconds += sdf.stats.seconds;
        benchmark::DoNotOptimize(sdf.distances.data());
        state.counters["voxels"] = double(sdf.distances.size());
        state.counters["rays/voxel"] = double(sdf.stats.signRays) / double(sdf.distances.size());
    }
    state.counters["triangles"] = double(mesh.triangleCount());
}
BENCHMARK(meshSdfBuild)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(2)->UseRealTime();

void bvhBuild(benchmark::State& state) {
    test::Mesh mesh;
    if (state.range(1) == 0) {
        mesh = test::makeRandomTriangles(uint32_t(state.range(0)), 1, 100.0f, 0.5f);
    } else { // structured: spheres of 81920 triangles in a row
        for (int i = 0; mesh.triangleCount() < size_t(state.range(0)); ++i) {
            mesh.append(test::makeIcosphere({3.0f * float(i), 0, 0}, 1.0f, 6));
        }
    }
    for (auto _ : state) {
        const bvh::Bvh bvh = bvh::buildBvh(mesh.positions, mesh.indices);
        benchmark::DoNotOptimize(bvh.nodes.data());
        state.counters["nodes"] = double(bvh.nodes.size());
        state.counters["sah"] = bvh::sahCost(bvh);
    }
    state.counters["triangles"] = double(mesh.triangleCount());
}
BENCHMARK(bvhBuild)
    ->Args({100000, 0})
    ->Args({1500000, 0})
    ->Args({1500000, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2)
    ->UseRealTime();

} // namespace
} // namespace lumina

BENCHMARK_MAIN();
