#pragma once
// What the device tells the network side: every line it says (serial's words: answers,
// errors, results) and every record made durable in the journal. Called on the device's
// thread in the middle of a measurement's report: an implementation copies into memory it
// sized before and returns at once; it never waits on a socket, and it drops rather than
// blocks.
#include <string_view>

#include "vision/luma_view.h"

namespace icacam::fw::net {

class DeviceListener {
public:
    virtual ~DeviceListener() = default;
    virtual void onLine(std::string_view line) = 0;
    // The record with this id is in the journal (fsynced).
    virtual void onJournaled(long id) = 0;
    // Aim mode's newest picture (before its "aim" line is said); valid during the call only.
    virtual void onAimPicture(const vision::LumaView &) {}
};

} // namespace icacam::fw::net
