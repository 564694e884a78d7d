#include "hal/file/file_led.h"

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace icacam::hal {

Error FileLed::open(const std::string &logPath)
{
    if (segments_ < 1)
        return Error::make(Errc::Invalid, "LED ring of " + std::to_string(segments_) + " segments: 1 or more");
    if (logPath.empty()) return {};
    fd_.reset(::open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644));
    if (!fd_.valid()) return Error::make(Errc::Io, "LED log '" + logPath + "': " + std::strerror(errno));
    return {};
}

Error FileLed::set(bool on)
{
    const int to = on ? kWholeRing : kDark;
    if (to != lit_) ++switches_;
    lit_ = to;
    if (light_) light_->switched(on);
    return log(on ? "on" : "off", -1);
}

Error FileLed::lightSegment(int k)
{
    if (segments_ <= 1) return Error::make(Errc::Invalid, "the LED ring is one line: no segment to light alone");
    if (k < 0 || k >= segments_)
        return Error::make(Errc::Invalid, "LED segment " + std::to_string(k) + ": the ring has " +
                                              std::to_string(segments_) + " (0 to " + std::to_string(segments_ - 1) +
                                              ")");
    if (k != lit_) ++switches_;
    lit_ = k;
    if (light_) light_->switchedSegment(k);
    return log("segment", k);
}

Error FileLed::log(const char *what, int k)
{
    if (!fd_.valid()) return {};
    char line[48];
    const long long ms = static_cast<long long>(clock_.monotonicMs());
    const int n = k < 0 ? std::snprintf(line, sizeof line, "%lld %s\n", ms, what)
                        : std::snprintf(line, sizeof line, "%lld %s %d\n", ms, what, k);
    if (::write(fd_.get(), line, size_t(n)) != n)
        return Error::make(Errc::Io, std::string("LED log: ") + std::strerror(errno));
    return {};
}

} // namespace icacam::hal
