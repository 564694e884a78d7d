// The commands, one by one: each answered on serial (and to the web, by its tag).
#include "firmware/device.h"

#include <algorithm>

namespace icacam::fw {

namespace {

// The keys settable over serial, for help and refusals.
std::string liveKeyList()
{
    std::string out;
    for (const std::string &k : configKeys(true)) out += (out.empty() ? "" : " ") + k;
    return out;
}

} // namespace

void Device::handleCommand(const Command &c)
{
    out_.clear();
    reading::JsonBuilder j(&out_);
    switch (c.kind) {
    case CommandKind::Help:
        j.str("type", "help")
            .str("commands", "status | trigger | get [KEY] | set KEY VALUE | results [N] | "
                             "scalecheck DIAMETER_MM [TOLERANCE_PCT [THICKNESS_MM]] | aim [SECONDS | off] | snapshot | "
                             "fetch NAME | lens POSITION | focus | measure-latency | help; "
                             "as words or JSON {\"cmd\":\"set\",\"key\":\"n\",\"value\":0.2,\"id\":\"x\"}")
            .str("keys", liveKeyList());
        break;
    case CommandKind::Status: appendStatus(j); break;
    case CommandKind::Trigger:
        if (aimUntilMs_ >= 0) stopAim("measurement");
        measure(lineOrigin_, c.tag);
        return;
    case CommandKind::Aim:
        if (c.aimSeconds == 0)
            stopAim("serial");
        else
            startAim(c.aimSeconds, c.tag);
        return;
    case CommandKind::Snapshot:
        if (aimUntilMs_ >= 0) stopAim("snapshot");
        snapshot(c);
        return;
    case CommandKind::Lens: setLens(c); return;
    case CommandKind::Focus:
        if (aimUntilMs_ >= 0) stopAim("focus");
        focus(c);
        return;
    case CommandKind::Fetch: fetch(c); return;
    case CommandKind::MeasureLatency:
        if (aimUntilMs_ >= 0) stopAim("measure-latency");
        measureLatency(c);
        return;
    case CommandKind::Get: {
        j.str("type", "settings");
        int matched = 0;
        for (const std::string &k : configKeys(true)) {
            if (!c.key.empty() && liveKeyName(c.key) != k) continue;
            std::string v;
            bool num = false;
            getConfigKey(cfg_, k, &v, &num);
            num ? j.raw(k, v) : j.str(k, v);
            ++matched;
        }
        if (matched == 0) {
            sendError("bad_argument", "unknown key (keys: " + liveKeyList() + ")", c.tag);
            return;
        }
        break;
    }
    case CommandKind::Set:
        if (!applySetting(c, j)) return;
        break;
    case CommandKind::Results: sendResults(c, j); return;
    case CommandKind::ScaleCheck:
        if (aimUntilMs_ >= 0) stopAim("scalecheck");
        scaleCheck(c);
        return;
    }
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
}

void Device::sendResults(const Command &c, reading::JsonBuilder &j)
{
    const size_t have = journal_.recentCount();
    const size_t n = std::min(have, size_t(c.count));
    j.str("type", "results").integer("count", static_cast<long long>(n));
    if (!c.tag.empty()) j.str("tag", c.tag);
    j.end();
    send(out_);
    for (size_t i = have - n; i < have; ++i) {
        // Measurements come back as records; scale checks as they were sent.
        const std::string_view line = journal_.recent(i), result = "{\"type\":\"result\"";
        if (line.substr(0, result.size()) == result) {
            out_.assign("{\"type\":\"record\"");
            out_.append(line.substr(result.size()));
        } else {
            out_.assign(line);
        }
        out_.push_back('\n');
        send(out_);
    }
}

} // namespace icacam::fw
