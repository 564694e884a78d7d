// libFuzzer target: the recipe's and the audit trail's readers take anything and answer with
// words, never a crash. The first byte picks what is fed: an audit trail and its head (split
// at the first NUL) to the checker, or `key = value` lines to a recipe applied on a valid
// config, whose canonical text must then read back to itself.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "firmware/audit_log.h"
#include "firmware/recipe.h"

using namespace icacam::fw;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    const std::string_view bytes(reinterpret_cast<const char *>(data) + 1, size - 1);
    if (data[0] % 2 == 0) {
        const size_t nul = bytes.find('\0');
        std::vector<AuditEntry> entries;
        const AuditCheck c = checkAudit(
            bytes.substr(0, nul), nul == std::string_view::npos ? std::string_view() : bytes.substr(nul + 1), &entries);
        // An entry handed out is one whose own hash and version hash held.
        for (const AuditEntry &e : entries)
            if (recipeHash(e.settings) != e.hash) std::abort();
        (void)c;
        return 0;
    }
    Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.01;
    if (!applyRecipeText(bytes, &cfg).empty()) return 0;
    // An accepted recipe's canonical text is a recipe that changes nothing.
    const std::string text = recipeText(cfg);
    Config again = cfg;
    if (!applyRecipeText(text, &again).empty() || recipeText(again) != text) std::abort();
    return 0;
}
