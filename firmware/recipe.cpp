#include "firmware/recipe.h"

#include <sodium.h>

#include <algorithm>
#include <vector>

namespace icacam::fw {

namespace {

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// The value of key in a canonical text ("" when absent).
std::string_view valueIn(std::string_view text, std::string_view key)
{
    while (!text.empty()) {
        const size_t nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        const size_t eq = line.find(" = ");
        if (eq != std::string_view::npos && line.substr(0, eq) == key) return line.substr(eq + 3);
    }
    return {};
}

} // namespace

bool isRecipeKey(std::string_view key)
{
    for (const char *k : kRecipeKeys)
        if (key == k) return true;
    return false;
}

std::string recipeKeyOf(std::string_view key)
{
    if (isRecipeKey(key)) return std::string(key);
    const std::string alias = liveKeyName(key);
    if (!alias.empty())
        for (const char *k : kRecipeKeys)
            if (liveKeyName(k) == alias) return k;
    return "";
}

bool validRecipeId(std::string_view id)
{
    if (id.empty() || id.size() > 32) return false;
    for (char c : id)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
              c == '.'))
            return false;
    return true;
}

std::string recipeText(const Config &cfg)
{
    std::string out;
    for (const char *k : kRecipeKeys) {
        std::string v;
        bool num = false;
        getConfigKey(cfg, k, &v, &num);
        ((out += k) += " = ") += v;
        out += '\n';
    }
    return out;
}

std::string recipeHash(std::string_view text)
{
    static const bool ready = sodium_init() >= 0; // thread-safe, once; SHA-256 needs no more
    (void)ready;
    unsigned char digest[crypto_hash_sha256_BYTES];
    crypto_hash_sha256(digest, reinterpret_cast<const unsigned char *>(text.data()), text.size());
    char hex[2 * crypto_hash_sha256_BYTES + 1];
    sodium_bin2hex(hex, sizeof hex, digest, sizeof digest);
    return hex;
}

std::string applyRecipeText(std::string_view text, Config *cfg)
{
    std::string problems;
    auto problem = [&problems](std::string_view p) { ((problems += problems.empty() ? "" : "; ") += p); };
    // The rules between keys: a recipe must not break one (those about the device's own keys
    // hold or not whatever the recipe says).
    const std::vector<std::string> before = crossKeyIssues(*cfg);
    int lineNo = 0;
    while (!text.empty()) {
        ++lineNo;
        const size_t nl = text.find('\n');
        const std::string_view line = trim(text.substr(0, nl));
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        if (line.empty()) continue;
        const size_t eq = line.find('=');
        if (eq == std::string_view::npos) {
            problem("line " + std::to_string(lineNo) + ": expected 'key = value'");
            continue;
        }
        const std::string_view key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
        if (!isRecipeKey(key)) {
            problem("'" + std::string(key.substr(0, 64)) + "' is not a recipe key");
            continue;
        }
        if (std::string e = setConfigKey(cfg, key, value, false); !e.empty()) problem(e);
    }
    if (!problems.empty()) return problems;
    for (const std::string &e : crossKeyIssues(*cfg))
        if (std::find(before.begin(), before.end(), e) == before.end()) problem(e);
    return problems;
}

std::string recipeChanges(std::string_view from, std::string_view to)
{
    std::string out;
    for (const char *k : kRecipeKeys) {
        const std::string_view a = valueIn(from, k), b = valueIn(to, k);
        if (a == b) continue;
        (((out += out.empty() ? "" : "; ") += k) += ": ") += a;
        (out += " -> ") += b;
    }
    return out;
}

} // namespace icacam::fw
