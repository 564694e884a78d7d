#pragma once
// The device's web page (web/index.html, built in): everything it needs comes from the
// device, no other site is asked.
namespace icacam::fw::net {

extern const char kWebPage[];

} // namespace icacam::fw::net
