#include "firmware/iso_time.h"

#include <cstdio>
#include <ctime>

namespace icacam::fw {

void isoTime(int64_t wallMs, char (&b)[96])
{
    const time_t s = time_t(wallMs / 1000);
    tm t{};
    gmtime_r(&s, &t);
    std::snprintf(b, sizeof b, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", t.tm_year + 1900, t.tm_mon + 1, t.tm_mday,
                  t.tm_hour, t.tm_min, t.tm_sec, int(wallMs % 1000));
}

} // namespace icacam::fw
