#include "firmware/net/line_exchange.h"

namespace icacam::fw::net {

LineExchange::LineExchange()
{
    for (std::string &s : lines_) s.reserve(kMaxLine);
}

void LineExchange::onLine(std::string_view line)
{
    if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
    std::lock_guard<std::mutex> lock(mutex_);
    // assign within the reserved capacity: no allocation on the device's thread
    lines_[head_].assign(line.substr(0, kMaxLine));
    head_ = (head_ + 1) % kLines;
    if (used_ < kLines) ++used_;
}

void LineExchange::onJournaled(long id)
{
    std::lock_guard<std::mutex> lock(mutex_);
    newest_ = id;
}

std::vector<std::string> LineExchange::answers(std::string_view tag) const
{
    std::string needle = "\"tag\":\"";
    needle.append(tag);
    needle.push_back('"');
    std::vector<std::string> out;
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < used_; ++i) {
        const std::string &s = lines_[(head_ + kLines - used_ + i) % kLines];
        if (s.find(needle) != std::string::npos && s.size() < kMaxLine) out.push_back(s);
    }
    return out;
}

std::string LineExchange::newestOfType(std::string_view type) const
{
    std::string prefix = "{\"type\":\"";
    prefix.append(type);
    prefix.push_back('"');
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = 0; i < used_; ++i) {
        const std::string &s = lines_[(head_ + kLines - 1 - i) % kLines];
        if (s.rfind(prefix, 0) == 0) return s;
    }
    return "";
}

long LineExchange::newestJournaled() const
{
    std::lock_guard<std::mutex> lock(mutex_);
    return newest_;
}

} // namespace icacam::fw::net
