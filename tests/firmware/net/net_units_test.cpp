// firmware/net's parts without sockets: the command inbox, the line exchange, the rate
// limiter, the journal tail, the PGM reader and the API's routes with a real password hash.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "firmware/journal.h"
#include "firmware/net/aim_exchange.h"
#include "firmware/net/command_inbox.h"
#include "firmware/net/journal_tail.h"
#include "firmware/net/line_exchange.h"
#include "firmware/net/pgm_png.h"
#include "firmware/net/rate_limiter.h"
#include "firmware/net/web_api.h"
#include "firmware/net/web_auth.h"
#include "firmware/recipe_book.h"
#include "firmware/recipe_desk.h"
#include "hal/file/folder_storage.h"
#include "reading/record_line.h"
#include "tests/support/temp_dir.h"

namespace icacam::fw::net {
namespace {

std::string record(long id, const char *extra = "")
{
    std::string line = "{\"type\":\"result\",\"id\":" + std::to_string(id) + ",\"mu\":0.1" + extra;
    reading::sealRecordLine(&line);
    return line + "\n";
}

TEST(CommandInbox, KeepsOrderRefusesWhenFullAndLinesTooLong)
{
    CommandInbox in;
    char out[CommandInbox::kMaxLine];
    EXPECT_EQ(in.pop(out), 0u);
    for (size_t i = 0; i < CommandInbox::kSlots; ++i) EXPECT_TRUE(in.push("status " + std::to_string(i)));
    EXPECT_FALSE(in.push("one too many"));
    EXPECT_FALSE(in.push(std::string(CommandInbox::kMaxLine + 1, 'x')));
    EXPECT_FALSE(in.push(""));
    const size_t n = in.pop(out);
    EXPECT_EQ(std::string(out, n), "status 0");
    EXPECT_TRUE(in.push("again"));
}

TEST(LineExchange, FindsAnswersByTheirWholeTag)
{
    LineExchange x;
    x.onLine("{\"type\":\"status\",\"tag\":\"web-1\"}\n");
    x.onLine("{\"type\":\"status\",\"tag\":\"web-12\"}\n");
    x.onLine("{\"type\":\"error\",\"message\":\"\\\"tag\\\":\\\"web-1\\\"\"}\n");
    const auto a = x.answers("web-1");
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0], "{\"type\":\"status\",\"tag\":\"web-1\"}");
    // Older lines give way to newer ones.
    for (size_t i = 0; i < LineExchange::kLines; ++i) x.onLine("{\"type\":\"x\"}");
    EXPECT_TRUE(x.answers("web-12").empty());
}

TEST(AimExchange, KeepsTheNewestPictureWithinItsSize)
{
    AimExchange aim;
    std::string png;
    long picture = -1;
    int step = 0;
    ASSERT_EQ(aim.png(&png, &picture, &step), "");
    EXPECT_EQ(picture, 0);
    std::vector<uint8_t> pixels(2000 * 1000, 7);
    aim.onAimPicture({pixels.data(), 2000, 1000, 2000, 1});
    ASSERT_EQ(aim.png(&png, &picture, &step), "");
    EXPECT_EQ(picture, 1);
    EXPECT_EQ(step, 3); // 2000 / 3 = 667 columns, within 800
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(RateLimiter, AllowsTheBurstThenTheRatePerAddress)
{
    RateLimiter r(10, 20);
    int allowed = 0;
    for (int i = 0; i < 100; ++i) allowed += r.allow(1, 1000);
    EXPECT_EQ(allowed, 20);
    EXPECT_TRUE(r.allow(2, 1000)); // another address has its own bucket
    EXPECT_FALSE(r.allow(1, 1050));
    EXPECT_TRUE(r.allow(1, 1100)); // 100 ms at 10/s: one more
}

TEST(JournalTail, IndexesIntactLinesAndLeavesATornTail)
{
    test::TempDir dir;
    const std::string path = dir.path + "/journal.jsonl";
    {
        std::ofstream f(path);
        f << record(1) << record(2) << "{\"type\":\"result\",\"id\":3,\"crc32\":\"00000000\"}\n"
          << record(4) << record(5).substr(0, 20);
    }
    JournalTail t(path);
    ASSERT_EQ(t.refresh(), "");
    EXPECT_EQ(t.newestId(), 4); // 3's seal is wrong, 5 is torn
    std::string line;
    EXPECT_FALSE(t.line(3, &line));
    ASSERT_TRUE(t.line(4, &line));
    EXPECT_EQ(Journal::checkLine(line), 4);
    EXPECT_EQ(t.after(1, 10).size(), 2u);
    ASSERT_EQ(t.last(1).size(), 1u);
    EXPECT_EQ(Journal::checkLine(t.last(1)[0]), 4);
    {
        std::ofstream f(path, std::ios::app);
        f << record(5).substr(20) << record(6);
    }
    ASSERT_EQ(t.refresh(), "");
    EXPECT_EQ(t.newestId(), 6);
    EXPECT_EQ(t.after(0, 100).size(), 5u);
}

TEST(PgmPng, RefusesBrokenHeadersAndShortPixels)
{
    PgmView v;
    EXPECT_NE(parsePgm("P6\n2 2\n255\n0000", &v), "");
    EXPECT_NE(parsePgm("P5\n2 2\n65535\n00000000", &v), "");
    EXPECT_NE(parsePgm("P5\n2 2\n255\n000", &v), "");
    EXPECT_NE(parsePgm("P5\n99999999 2\n255\n", &v), "");
    ASSERT_EQ(parsePgm("P5\n# a comment\n3 2\n255\nabcdef", &v), "");
    EXPECT_EQ(v.width, 3);
    std::string png;
    ASSERT_EQ(pgmToPng(v, 2, &png), "");
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_NE(pgmToPng(v, 9, &png), "");
}

TEST(WebQuery, ValuesAndWholeNumbers)
{
    std::string_view v;
    EXPECT_TRUE(queryValue("a=1&id=42&b", "id", &v));
    EXPECT_EQ(v, "42");
    EXPECT_TRUE(queryValue("a=1&id=42&b", "b", &v));
    EXPECT_FALSE(queryValue("a=1", "id", &v));
    long n = 0;
    EXPECT_TRUE(parseWhole("42", 1, 100, &n));
    EXPECT_FALSE(parseWhole("4x", 1, 100, &n));
    EXPECT_FALSE(parseWhole("", 1, 100, &n));
    EXPECT_FALSE(parseWhole("101", 1, 100, &n));
    EXPECT_FALSE(parseWhole("99999999999999999999999", 1, 100, &n));
}

class WebApiTest : public ::testing::Test {
protected:
    void SetUp() override { std::ofstream(dir.path + "/journal.jsonl") << record(1) << record(2); }
    HttpResponse call(const char *method, const char *path, const char *query = "", std::string_view body = "",
                      std::string_view session = "")
    {
        HttpRequest r;
        r.method = method;
        r.path = path;
        r.query = query;
        r.body = body;
        r.contentType = "application/json";
        r.session = session;
        r.nowMs = now += 60000; // past any hold-off (a second after a check that may take seconds)
        return api.handle(r);
    }
    std::string login()
    {
        const HttpResponse r = call("POST", "/api/login", "", "{\"password\":\"pw\"}");
        EXPECT_EQ(r.status, 200) << r.body;
        const size_t eq = r.setCookie.find('='), semi = r.setCookie.find(';');
        return r.setCookie.substr(eq + 1, semi - eq - 1);
    }
    test::TempDir dir;
    JournalTail tail{dir.path + "/journal.jsonl"};
    CommandInbox inbox;
    LineExchange lines;
    AimExchange aim;
    WebAuth auth{WebAuth::hash("pw")};
    WebApi api{WebContext{tail, dir.path, inbox, lines, aim, auth, false, false}};
    int64_t now = 1000;
};

TEST_F(WebApiTest, ReadingNeedsALoginUnlessOpen)
{
    EXPECT_EQ(call("GET", "/").status, 200);
    EXPECT_EQ(call("GET", "/api/results").status, 401);
    EXPECT_EQ(call("POST", "/api/login", "", "{\"password\":\"nope\"}").status, 401);
    const std::string token = login();
    const HttpResponse r = call("GET", "/api/results", "after=1", "", token);
    EXPECT_EQ(r.status, 200);
    EXPECT_NE(r.body.find("\"id\":2"), std::string::npos);
    EXPECT_EQ(r.body.find("\"id\":1,"), std::string::npos);
    EXPECT_EQ(call("POST", "/api/logout", "", "", token).status, 200);
    EXPECT_EQ(call("GET", "/api/results", "", "", token).status, 401);
}

TEST_F(WebApiTest, CommandsAreQueuedWithATagAndChangesNeedALogin)
{
    WebAuth open{""};
    WebApi openApi{WebContext{tail, dir.path, inbox, lines, aim, open, true, false}};
    HttpRequest r;
    r.method = "POST";
    r.path = "/api/command";
    r.contentType = "application/json";
    r.body = "{\"cmd\":\"status\",\"id\":\"mine\"}";
    EXPECT_EQ(openApi.handle(r).status, 202); // reading is open
    r.body = "{\"cmd\":\"trigger\"}";
    EXPECT_EQ(openApi.handle(r).status, 401); // measuring is not
    char line[CommandInbox::kMaxLine];
    const size_t n = inbox.pop(line);
    EXPECT_EQ(std::string(line, n), "{\"cmd\":\"status\",\"id\":\"web-1\"}");

    const std::string token = login();
    const HttpResponse q = call("POST", "/api/command", "", "{\"cmd\":\"set\",\"key\":\"n\",\"value\":0.2}", token);
    EXPECT_EQ(q.status, 202);
    EXPECT_NE(q.body.find("\"tag\":\"web-"), std::string::npos);
    EXPECT_EQ(call("POST", "/api/command", "", "{\"cmd\":\"results\"}", token).status, 400);
    EXPECT_EQ(call("POST", "/api/command", "", "status", token).status, 400);
    EXPECT_EQ(call("POST", "/api/command", "", "{\"cmd\":\"trigger\"", token).status, 400);
}

TEST_F(WebApiTest, PathsAndArgumentsAreChecked)
{
    const std::string token = login();
    EXPECT_EQ(call("GET", "/api/../journal.jsonl", "", "", token).status, 400);
    EXPECT_EQ(call("GET", "/api/result", "id=abc", "", token).status, 400);
    EXPECT_EQ(call("GET", "/api/result", "id=7", "", token).status, 404);
    EXPECT_EQ(call("GET", "/api/image", "id=1", "", token).status, 404); // the record names no frame
    EXPECT_EQ(call("GET", "/api/results", "limit=0", "", token).status, 400);
    EXPECT_EQ(call("DELETE", "/api/results", "", "", token).status, 405);
    EXPECT_EQ(call("POST", "/api/command", "", std::string(WebApi::kMaxBody + 1, ' '), token).status, 413);
    const HttpResponse csv = call("GET", "/api/results.csv", "", "", token);
    EXPECT_EQ(csv.status, 200);
    EXPECT_EQ(csv.body.substr(0, 8), "id,time,");
}

TEST_F(WebApiTest, RecipeSavesNeedALoginAReasonAndRecipeKeys)
{
    RecipeDesk desk;
    WebApi withRecipes{WebContext{tail, dir.path, inbox, lines, aim, auth, false, false, &desk}};
    // The device's recipe as published, and its trail as written.
    hal::FolderStorage storage;
    ASSERT_TRUE(storage.open(dir.path, 0).ok());
    RecipeBook book(storage);
    Config cfg;
    cfg.n = 0.2;
    cfg.mmPerPx = 0.01;
    std::vector<std::string> problems;
    ASSERT_TRUE(book.start(cfg, &cfg, "2026-01-01T00:00:00Z", &problems).ok());
    desk.publish(book.active(), "");
    auto call2 = [&](const char *method, const char *path, std::string body, const std::string &session,
                     std::string query = "") {
        HttpRequest r;
        r.method = method;
        r.path = path;
        r.query = query;
        r.body = body;
        r.contentType = "application/json";
        r.session = session;
        r.nowMs = now += 2000;
        return withRecipes.handle(r);
    };
    const HttpResponse in = call2("POST", "/api/login", "{\"password\":\"pw\",\"user\":\"alice\"}", "");
    ASSERT_EQ(in.status, 200);
    const std::string token = in.setCookie.substr(in.setCookie.find('=') + 1, 64);
    EXPECT_EQ(call2("POST", "/api/recipe", "{\"reason\":\"x\",\"specimen.n\":0.3}", "").status, 401);
    EXPECT_EQ(call2("POST", "/api/recipe", "{\"specimen.n\":0.3}", token).status, 400); // no reason
    EXPECT_EQ(call2("POST", "/api/recipe", "{\"reason\":\"x\",\"journal.dir\":\"/\"}", token).status, 400);
    // A value with a line break would smuggle in another key: refused.
    EXPECT_EQ(
        call2("POST", "/api/recipe", "{\"reason\":\"x\",\"specimen.material\":\"a\\nspecimen.n = 9\"}", token).status,
        400);
    EXPECT_EQ(call2("POST", "/api/live", "{\"specimen.n\":0.3}", token).status, 400); // live: camera keys only
    const HttpResponse q = call2("POST", "/api/recipe", "{\"reason\":\"new batch\",\"specimen.n\":0.3}", token);
    EXPECT_EQ(q.status, 202) << q.body;
    EXPECT_EQ(call2("POST", "/api/recipe", "{\"reason\":\"again\",\"specimen.n\":0.3}", token).status, 503);
    RecipeDesk::Request got;
    ASSERT_TRUE(desk.take(&got));
    EXPECT_EQ(got.who, "alice (web)");
    EXPECT_EQ(got.why, "new batch");
    EXPECT_EQ(got.text, "specimen.n = 0.3\n");

    const HttpResponse r = call2("GET", "/api/recipe", "", token);
    EXPECT_NE(r.body.find("\"version\":1"), std::string::npos) << r.body;
    EXPECT_NE(r.body.find("\"specimen.n\":\"0.2\""), std::string::npos) << r.body;
    EXPECT_NE(call2("GET", "/api/recipe/versions", "", token).body.find("\"who\":\"config file\""), std::string::npos);
    EXPECT_EQ(call2("GET", "/api/recipe/version", "", token, "recipe=default&version=1").status, 200);
    EXPECT_EQ(call2("GET", "/api/recipe/version", "", token, "recipe=default&version=2").status, 404);
    EXPECT_NE(call2("GET", "/api/audit", "", token).body.find("\"intact\":true"), std::string::npos);
    // One byte of the trail changed: the API says so.
    hal::Result<std::string> log = storage.read(kAuditFile);
    ASSERT_TRUE(log.ok());
    log.value[log.value.find("first version")] = 'F';
    ASSERT_TRUE(storage.writeAtomic(kAuditFile, log.value).ok());
    const HttpResponse damaged = call2("GET", "/api/audit", "", token);
    EXPECT_NE(damaged.body.find("\"intact\":false"), std::string::npos) << damaged.body;
    EXPECT_NE(damaged.body.find("\"problems\":[\"line 1 (entry 1): altered"), std::string::npos) << damaged.body;
}

} // namespace
} // namespace icacam::fw::net
