// libFuzzer target: the web API's parsers must answer anything with a status, never crash.
// The first byte picks what is fed: a request (method, "path?query", '\n', body) to the
// routes, a frame to the PGM reader and PNG writer, or a journal to the journal tail.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/journal_tail.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/pgm_png.h"
#include "firmware/net/web_api.h"
#include "firmware/net/web_auth.h"

namespace {

using namespace icacam::fw::net;

struct World {
    std::string dir;
    JournalTail tail;
    CommandInbox inbox;
    LineExchange lines;
    AimExchange aim;
    WebAuth auth{""}; // no password: a login is refused at once (a real one costs 0.1 s)
    WebApi api;
    static std::string makeDir()
    {
        char tmpl[] = "/tmp/icacam-fuzz-web-XXXXXX";
        return mkdtemp(tmpl);
    }
    World()
            : dir(makeDir()), tail(dir + "/journal.jsonl"),
              api(WebContext{tail, dir, inbox, lines, aim, auth, true, false})
    {
        std::ofstream(dir + "/journal.jsonl") << "{\"type\":\"result\",\"id\":1,\"crc32\":\"00000000\"}\n";
    }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static World w;
    if (size < 2) return 0;
    const std::string_view bytes(reinterpret_cast<const char *>(data) + 2, size - 2);
    switch (data[0] % 3) {
    case 0: {
        static const char *const kMethods[] = {"GET", "POST", "HEAD", "PUT"};
        const size_t nl = bytes.find('\n');
        const std::string_view target = bytes.substr(0, nl);
        const size_t q = target.find('?');
        HttpRequest r;
        r.method = kMethods[data[1] % 4];
        r.path = target.substr(0, q);
        r.query = q == std::string_view::npos ? std::string_view() : target.substr(q + 1);
        r.body = nl == std::string_view::npos ? std::string_view() : bytes.substr(nl + 1);
        r.contentType = (data[1] & 4) ? "application/json" : "text/plain";
        r.nowMs = 1;
        const HttpResponse out = w.api.handle(r);
        if (out.status < 200 || out.status > 599) __builtin_trap();
        char line[CommandInbox::kMaxLine];
        while (w.inbox.pop(line) > 0) {}
        break;
    }
    case 1: {
        PgmView v;
        std::string png;
        if (parsePgm(bytes, &v).empty() && size_t(v.width) * size_t(v.height) <= 1 << 20)
            (void)pgmToPng(v, 1 + data[1] % 8, &png);
        break;
    }
    case 2: {
        std::ofstream(w.dir + "/journal.jsonl", std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
        JournalTail t(w.dir + "/journal.jsonl");
        (void)t.refresh();
        std::string line;
        (void)t.line(1, &line);
        (void)t.last(3);
        break;
    }
    }
    return 0;
}
