#include "firmware/net/web_auth.h"

#include <sodium.h>

#include <chrono>
#include <cstring>

namespace icacam::fw::net {

namespace {

bool sodiumReady()
{
    static const bool ok = sodium_init() >= 0;
    return ok;
}

} // namespace

WebAuth::WebAuth(std::string storedHash) : hash_(std::move(storedHash))
{
    while (!hash_.empty() && (hash_.back() == '\n' || hash_.back() == '\r' || hash_.back() == ' ')) hash_.pop_back();
}

std::string WebAuth::hash(std::string_view password)
{
    if (!sodiumReady()) return "";
    char out[crypto_pwhash_STRBYTES];
    if (crypto_pwhash_str(out, password.data(), password.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                          crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0)
        return "";
    return out;
}

WebAuth::Login WebAuth::login(std::string_view password, int64_t nowMs, std::string *token, std::string_view user)
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (hash_.empty()) return Login::NoPassword;
        if (nowMs < heldUntilMs_) return Login::HeldOff;
        // Set before the (slow) check: a second attempt meanwhile is held off too.
        heldUntilMs_ = INT64_MAX;
    }
    const auto checkStart = std::chrono::steady_clock::now();
    if (!sodiumReady() || password.size() > 256 ||
        crypto_pwhash_str_verify(hash_.c_str(), password.data(), password.size()) != 0) {
        // The second counts from the answer, not the attempt: where the check itself takes
        // a second or more (a slow board, an emulator) the next guess is still held off.
        const int64_t checkMs =
            std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - checkStart)
                .count();
        std::lock_guard<std::mutex> lock(mutex_);
        heldUntilMs_ = nowMs + checkMs + kHoldOffMs;
        return Login::Wrong;
    }
    unsigned char raw[32];
    randombytes_buf(raw, sizeof raw);
    char hex[65];
    sodium_bin2hex(hex, sizeof hex, raw, sizeof raw);
    std::lock_guard<std::mutex> lock(mutex_);
    heldUntilMs_ = 0;
    Session *slot = &sessions_[0];
    for (Session &s : sessions_)
        if (s.lastMs < slot->lastMs) slot = &s; // the longest idle (or a free one) makes room
    std::memcpy(slot->token.data(), hex, sizeof hex);
    slot->user = {};
    user.substr(0, kMaxUser).copy(slot->user.data(), kMaxUser);
    slot->lastMs = nowMs;
    *token = hex;
    return Login::Ok;
}

bool WebAuth::valid(std::string_view token, int64_t nowMs, std::string *user)
{
    if (token.size() != 64) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    for (Session &s : sessions_) {
        if (s.lastMs == 0 || nowMs - s.lastMs > kIdleMs) continue;
        if (sodium_memcmp(s.token.data(), token.data(), 64) == 0) {
            s.lastMs = nowMs;
            if (user) *user = s.user.data();
            return true;
        }
    }
    return false;
}

void WebAuth::logout(std::string_view token)
{
    std::lock_guard<std::mutex> lock(mutex_);
    for (Session &s : sessions_)
        if (token.size() == 64 && std::memcmp(s.token.data(), token.data(), 64) == 0) s = Session{};
}

} // namespace icacam::fw::net
