#include "gi/core/build_info.h"

#include "lumina_build_info.h" // generated: LUMINA_GIT_COMMIT

namespace lumina::gi {

std::string_view gitCommit() {
    return LUMINA_GIT_COMMIT;
}

} // namespace lumina::gi
