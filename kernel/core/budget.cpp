// The words of a budget's target.
#include "kernel/core/budget.h"

namespace raster {

const char* cost_target_name(CostTarget t) { return t == CostTarget::I486 ? "486" : t == CostTarget::Pentium ? "pentium" : "icount"; }

bool cost_target_named(const char* word, size_t length, CostTarget* t) {
    for (int i = 0; i < int(CostTarget::Count); ++i) {
        const char* name = cost_target_name(CostTarget(i));
        size_t n = 0;
        while (name[n] && n < length && name[n] == word[n]) ++n;
        if (!name[n] && n == length) {
            *t = CostTarget(i);
            return true;
        }
    }
    return false;
}

}  // namespace raster
