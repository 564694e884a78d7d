#pragma once
// The web login: one password per device, stored only as a salted Argon2id hash
// (libsodium's crypto_pwhash_str, the string `icacam-fw --hash-password` and
// deploy/install.sh write), and sessions as random tokens with an idle time-out. A wrong
// password holds off the next attempt for a second after its answer, whoever makes it.
#include <array>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>

namespace icacam::fw::net {

class WebAuth {
public:
    static constexpr int kSessions = 16;
    static constexpr int64_t kIdleMs = 8 * 3600 * 1000;
    static constexpr int64_t kHoldOffMs = 1000;
    enum class Login { Ok, Wrong, HeldOff, NoPassword };

    // storedHash: the password file's first line ("" = no password set: nobody logs in).
    explicit WebAuth(std::string storedHash);
    // user: the name the person gave at login (there is one password, not one per person):
    // the audit trail's "who" for what the session changes. Up to kMaxUser characters.
    static constexpr size_t kMaxUser = 32;
    Login login(std::string_view password, int64_t nowMs, std::string *token, std::string_view user = {});
    // True for a live session (its idle time restarts); its user's name into *user.
    bool valid(std::string_view token, int64_t nowMs, std::string *user = nullptr);
    void logout(std::string_view token);

    // The stored form of a password, "" when libsodium fails (out of memory).
    static std::string hash(std::string_view password);

private:
    struct Session {
        std::array<char, 65> token{};
        std::array<char, kMaxUser + 1> user{};
        int64_t lastMs = 0;
    };
    std::string hash_;
    std::mutex mutex_;
    std::array<Session, kSessions> sessions_{};
    int64_t heldUntilMs_ = 0;
};

} // namespace icacam::fw::net
