#include <gtest/gtest.h>

#include <random>
#include <string>

#include "firmware/command.h"
#include "reading/record_line.h"

using namespace icacam;
using namespace icacam::fw;

TEST(Command, JsonAndWordsMeanTheSame)
{
    auto a = parseCommand(R"({"cmd":"set","key":"n","value":0.25,"id":"q1"})");
    ASSERT_TRUE(a.ok) << a.message;
    EXPECT_EQ(a.cmd.kind, CommandKind::Set);
    EXPECT_EQ(a.cmd.key, "n");
    EXPECT_EQ(a.cmd.value, "0.25");
    EXPECT_EQ(a.cmd.tag, "q1");
    auto b = parseCommand("set n 0.25\r");
    ASSERT_TRUE(b.ok);
    EXPECT_EQ(b.cmd.key, "n");
    EXPECT_EQ(b.cmd.value, "0.25");
    auto r = parseCommand(R"({"cmd":"results","n":5})");
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.cmd.count, 5);
    EXPECT_EQ(parseCommand("results 7").cmd.count, 7);
    EXPECT_TRUE(parseCommand("  status ").ok);
}

TEST(Command, RefusalsCarryACodeAndWords)
{
    struct Case {
        const char *line, *code;
    } cases[] = {
        {"", "malformed"},
        {"{", "malformed"},
        {R"({"cmd":"status"} x)", "malformed"},
        {R"({"cmd":["status"]})", "malformed"},
        {R"({"nocmd":1})", "malformed"},
        {R"({"cmd":"launch"})", "unknown_command"},
        {"reboot now", "unknown_command"},
        {"set n", "bad_argument"},
        {"results 0", "bad_argument"},
        {"results 1e9", "bad_argument"},
        {"results 2.5", "bad_argument"},
        {R"({"cmd":"results","n":-1})", "bad_argument"},
        {R"({"cmd":"set","key":"n"})", "bad_argument"},
        {"status please", "bad_argument"},
        {R"({"cmd":"status","a":1,"a":2})", "malformed"},
        {R"({"cmd":"st\u0000atus"})", "unknown_command"},
        {"scalecheck", "bad_argument"},
        {"scalecheck ten", "bad_argument"},
        {"scalecheck 0.2", "bad_argument"},
        {"scalecheck 20 50", "bad_argument"},
        {"scalecheck 20 0.5 1 9", "bad_argument"},
        {"set n 0.2 0.3", "bad_argument"},
        {R"({"cmd":"scalecheck"})", "bad_argument"},
        {R"({"cmd":"scalecheck","diameter_mm":"20"})", "bad_argument"},
        {R"({"cmd":"scalecheck","diameter_mm":20,"thickness_mm":-1})", "bad_argument"},
    };
    for (const auto &c : cases) {
        auto p = parseCommand(c.line);
        EXPECT_FALSE(p.ok) << c.line;
        EXPECT_STREQ(p.code, c.code) << c.line;
        EXPECT_FALSE(p.message.empty()) << c.line;
    }
}

TEST(Command, ScaleCheckAsWordsAndJson)
{
    auto w = parseCommand("scalecheck 20 0.25 1.5");
    ASSERT_TRUE(w.ok) << w.message;
    EXPECT_EQ(w.cmd.kind, CommandKind::ScaleCheck);
    EXPECT_DOUBLE_EQ(w.cmd.diameterMm, 20);
    EXPECT_DOUBLE_EQ(w.cmd.tolerancePct, 0.25);
    EXPECT_DOUBLE_EQ(w.cmd.thicknessMm, 1.5);
    auto d = parseCommand("scalecheck 12");
    ASSERT_TRUE(d.ok);
    EXPECT_DOUBLE_EQ(d.cmd.tolerancePct, 0.5); // the default
    EXPECT_DOUBLE_EQ(d.cmd.thicknessMm, 0);
    auto j = parseCommand(R"({"cmd":"scalecheck","diameter_mm":12.5,"tolerance_pct":1,"id":"k"})");
    ASSERT_TRUE(j.ok) << j.message;
    EXPECT_DOUBLE_EQ(j.cmd.diameterMm, 12.5);
    EXPECT_DOUBLE_EQ(j.cmd.tolerancePct, 1);
    EXPECT_EQ(j.cmd.tag, "k");
}

TEST(Command, RandomBytesNeverParseSilently)
{
    std::mt19937 rng(42);
    for (int i = 0; i < 20000; ++i) {
        std::string s(size_t(rng() % 64), '\0');
        for (char &ch : s) ch = char(rng() % 256);
        auto p = parseCommand(s);
        if (!p.ok) { EXPECT_FALSE(p.message.empty()); }
    }
}

TEST(LineAssembler, OversizedLineIsReportedOnceAndDropped)
{
    LineAssembler a(16);
    std::string input = "status\n" + std::string(1000000, 'x') + "\nhelp\n";
    std::string_view rest = input;
    std::vector<std::string> lines;
    int overflows = 0;
    for (;;) {
        auto ev = a.push(&rest);
        if (ev == LineAssembler::Event::None) break;
        if (ev == LineAssembler::Event::Overflow)
            ++overflows;
        else
            lines.emplace_back(a.line());
    }
    EXPECT_EQ(overflows, 1);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "status");
    EXPECT_EQ(lines[1], "help");
}

TEST(LineAssembler, LinesSplitAcrossReads)
{
    LineAssembler a(64);
    std::string_view p1 = "sta", p2 = "tus\nhe";
    EXPECT_EQ(a.push(&p1), LineAssembler::Event::None);
    EXPECT_EQ(a.push(&p2), LineAssembler::Event::Line);
    EXPECT_EQ(a.line(), "status");
    EXPECT_EQ(a.push(&p2), LineAssembler::Event::None);
}

TEST(Json, BuilderEscapesAndParserReadsBack)
{
    std::string out;
    reading::JsonBuilder(&out).str("a", "q\"\\\n\x01").num("b", 0.125).integer("c", -3).boolean("d", true).end();
    EXPECT_EQ(out, "{\"a\":\"q\\\"\\\\\\n\\u0001\",\"b\":0.125,\"c\":-3,\"d\":true}\n");
    reading::FlatObject o;
    ASSERT_EQ(reading::parseFlatObject(out.substr(0, out.size() - 1), &o), "");
    EXPECT_EQ(o.find("a")->text, "q\"\\\n\x01");
    EXPECT_DOUBLE_EQ(o.find("b")->number, 0.125);
    EXPECT_TRUE(o.find("d")->boolean);
}
