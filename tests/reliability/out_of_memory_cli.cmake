# An allocation the GPU cannot give ends `lumina render` and `lumina reference` with exit code
# 1 and a message that names the resource, its size and what to make smaller: never a crash,
# a hang or a driver's undefined behaviour. 16384x16384 is the largest --size the CLI accepts;
# its float4 buffers and images need 4 GiB each, more than lavapipe (2 GiB) or most GPUs
# allocate at once, so the RHI refuses them before creating anything.
include(${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake)

run(1 reference reference cornell_box --size 16384x16384 --spp 1 --out oom_reference.exr)
# Nothing written, the resource named with its size, and the way out.
expect_match(reference "${ERR}" "lumina: error: out of GPU memory: 'path tracer: mean' needs 4096 MiB, and [^\n]* allocates at most [0-9]+ MiB at once")
expect_match(reference "${ERR}" "a smaller --size, a lower --preset or a smaller scene")

run(1 render render cornell_box --size 16384x16384 --technique direct --frames 1 --out oom_render.png)
expect_match(render "${ERR}" "lumina: error: out of GPU memory: '[^']+' needs [0-9]+ MiB")
expect_match(render "${ERR}" "a smaller --size, a lower --preset or a smaller scene")
