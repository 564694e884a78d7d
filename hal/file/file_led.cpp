#include "hal/file/file_led.h"

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace icacam::hal {

Error FileLed::open(const std::string &logPath)
{
    if (logPath.empty()) return {};
    fd_.reset(::open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644));
    if (!fd_.valid()) return Error::make(Errc::Io, "LED log '" + logPath + "': " + std::strerror(errno));
    return {};
}

Error FileLed::set(bool on)
{
    if (on != on_) ++switches_;
    on_ = on;
    if (light_) light_->switched(on);
    if (!fd_.valid()) return {};
    char line[48];
    const int n =
        std::snprintf(line, sizeof line, "%lld %s\n", static_cast<long long>(clock_.monotonicMs()), on ? "on" : "off");
    if (::write(fd_.get(), line, size_t(n)) != n)
        return Error::make(Errc::Io, std::string("LED log: ") + std::strerror(errno));
    return {};
}

} // namespace icacam::hal
