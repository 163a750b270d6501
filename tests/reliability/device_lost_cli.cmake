# A GPU lost in the middle of `lumina reference` and `lumina render` (docs/gi_tests.md#device-loss):
# the device is made to report VK_ERROR_DEVICE_LOST at a chosen submission and every wait after
# it (LUMINA_FAULT_INJECT, rhi/fault_injection.h), as a real lost device does; each run must end
# within its time bound with exit code 1, the loss named, and no image written. Then a plan the
# hook does not know is an error naming the variable. LUMINA: the CLI; WORK: a scratch folder.
include(${CMAKE_CURRENT_LIST_DIR}/bounded_run.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# lost_message(<submissions>): sets LOST, the message of a loss injected after that many submissions.
function(lost_message submissions)
  set(LOST "lumina: error: the GPU device was lost: vkQueueSubmit2 failed: VK_ERROR_DEVICE_LOST \\(-4\\) \\[[a-z]+ queue, value [0-9]+; injected by LUMINA_FAULT_INJECT=device-lost-after-submits:${submissions}\\]" PARENT_SCOPE)
endfunction()

# The 17th submission is the path tracer's, after some samples (measured on lavapipe: the first 8
# upload the scene and build the BVH): the loss comes in the middle of the render.
set(ENV{LUMINA_FAULT_INJECT} "device-lost-after-submits:16")
lost_message(16)
bounded_run(1 reference 120 "${LUMINA}" reference cornell_box --size 32x32 --spp 64 --out "${WORK}/reference.exr")
expect_match(reference "${ERR}" "[1-9][0-9]*/64 spp.*${LOST}")

# The 21st is a frame's, after the lumen technique's setup (it prints its memory once made).
set(ENV{LUMINA_FAULT_INJECT} "device-lost-after-submits:20")
lost_message(20)
bounded_run(1 render 120 "${LUMINA}" render cornell_box --size 32x32 --technique lumen --preset low --frames 8
            --out "${WORK}/render.png")
expect_match(render "${OUT}" "GPU memory: ")
expect_match(render "${ERR}" "${LOST}")

# Lost at the very first submission (the scene's upload), under the validation layer: the
# teardown after a loss destroys nothing still in use.
set(ENV{LUMINA_FAULT_INJECT} "device-lost-after-submits:0")
lost_message(0)
bounded_run(1 first-submission 120 "${LUMINA}" render cornell_box --size 32x32 --technique lumen --preset low
            --frames 8 --validation --out "${WORK}/first.png")
expect_match(first-submission "${ERR}" "${LOST}")
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[first-submission] validation messages:\n${ERR}")
endif()

foreach(image reference.exr render.png first.png)
  if(EXISTS "${WORK}/${image}")
    message(FATAL_ERROR "${image} was written by a run whose device was lost")
  endif()
endforeach()

set(ENV{LUMINA_FAULT_INJECT} "device-lost-after-frames:3")
bounded_run(1 unknown-fault 120 "${LUMINA}" render cornell_box --size 16x16 --technique direct --frames 1
            --out "${WORK}/unknown.png")
expect_match(unknown-fault "${ERR}" "LUMINA_FAULT_INJECT='device-lost-after-frames:3': not a fault this build injects")
