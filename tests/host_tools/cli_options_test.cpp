// The option reader every `icacam` subcommand uses (host_tools/cli_options.h), and the help
// texts: the model names come from the factory and the stated defaults are the code's.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

#include "friction/friction_models.h"
#include "host_tools/cli_options.h"
#include "host_tools/fe/fe_command.h"
#include "host_tools/loop/loop_command.h"
#include "host_tools/measure_command.h"

using icacam::host::cli::OptionReader;
using icacam::host::cli::UsageError;

namespace {

struct Read {
    std::string out;
    bool hard = false;
    double count = 0;
};

Read readArgs(const std::vector<std::string> &args)
{
    Read r;
    OptionReader opts(args, "usage: test\n");
    while (opts.next()) {
        if (opts.is("--out"))
            r.out = opts.value();
        else if (opts.is("--hard"))
            r.hard = opts.flag();
        else if (opts.is("--count"))
            r.count = double(opts.wholeNumber(1, 100));
        else
            opts.unknown();
    }
    return r;
}

std::string errorOf(const std::vector<std::string> &args)
{
    try {
        readArgs(args);
    } catch (const UsageError &e) {
        EXPECT_EQ(e.usage(), "usage: test\n");
        return e.what();
    }
    return "";
}

// What a command prints on standard output.
template <class F> std::string printed(F run)
{
    std::ostringstream text;
    std::streambuf *old = std::cout.rdbuf(text.rdbuf());
    const int rc = run();
    std::cout.rdbuf(old);
    EXPECT_EQ(rc, 0);
    return text.str();
}

} // namespace

TEST(OptionReader, SpaceAndEqualsFormsReadTheSame)
{
    const Read a = readArgs({"--out", "dir", "--count", "7", "--hard"});
    const Read b = readArgs({"--out=dir", "--count=7", "--hard"});
    EXPECT_EQ(a.out, "dir");
    EXPECT_EQ(b.out, "dir");
    EXPECT_EQ(a.count, 7);
    EXPECT_EQ(b.count, 7);
    EXPECT_TRUE(a.hard && b.hard);
    EXPECT_EQ(readArgs({"--out="}).out, "");                // an explicit empty value
    EXPECT_EQ(readArgs({"--out", "--hard"}).out, "--hard"); // a value may look like an option
}

TEST(OptionReader, MistakesNameTheOption)
{
    EXPECT_EQ(errorOf({"--out"}), "--out needs a value");
    EXPECT_EQ(errorOf({"--bogus"}), "unknown option '--bogus'");
    EXPECT_EQ(errorOf({"--bogus=3"}), "unknown option '--bogus'");
    EXPECT_EQ(errorOf({"stray"}), "unexpected argument 'stray'");
    EXPECT_EQ(errorOf({"--hard=1"}), "--hard: takes no value (given '1')");
    EXPECT_EQ(errorOf({"--count", "x"}), "--count: a whole number from 1 to 100, not 'x'");
    EXPECT_EQ(errorOf({"--count=2.5"}), "--count: a whole number from 1 to 100, not '2.5'");
    EXPECT_EQ(errorOf({"--count", "101"}), "--count: a whole number from 1 to 100, not '101'");
    EXPECT_EQ(errorOf({"--count", "3", "--out", "d"}), "");
}

TEST(OptionReader, NumbersAreWholeStrings)
{
    double v = 0;
    EXPECT_TRUE(icacam::host::cli::parseFinite("1e5", &v));
    EXPECT_EQ(v, 1e5);
    EXPECT_TRUE(icacam::host::cli::parseFinite("-0.25", &v));
    EXPECT_EQ(v, -0.25);
    for (const char *bad : {"", " 1", "1 ", "1x", "nan", "inf", "0x"})
        EXPECT_FALSE(icacam::host::cli::parseFinite(bad, &v)) << bad;
}

TEST(Help, ListsTheFactorysModelsAndDefault)
{
    const std::string names = icacam::host::cli::modelNames();
    std::string joined;
    for (std::string_view n : icacam::friction::kModelNames) {
        EXPECT_NE(icacam::friction::frictionModel(n), nullptr) << n;
        joined += (joined.empty() ? "" : ", ") + std::string(n);
    }
    EXPECT_EQ(names, joined);
    const std::string def = std::string("default ") + icacam::friction::kDefaultModel + "; known: " + names;
    EXPECT_NE(printed([] { return icacam::host::measureCommand({"--help"}); }).find(def), std::string::npos);
    EXPECT_NE(printed([] { return icacam::host::loopCommand({"--help"}); }).find(def), std::string::npos);
}

TEST(Help, AnUnknownModelIsAUsageError)
{
    EXPECT_THROW(icacam::host::measureCommand({"--manifest", "m.csv", "--model", "nope"}), UsageError);
    EXPECT_THROW(icacam::host::loopCommand({"--manifest", "m.csv", "--report", "r", "--model=nope"}), UsageError);
}

TEST(Help, FeHelpIsAnsweredByTheCommand)
{
    // Every verb's --help returns (no exit from inside the parser) with the same text.
    const std::string top = printed([] { return icacam::host::feCommand({"--help"}); });
    EXPECT_NE(top.find("--preset coarse|base"), std::string::npos) << top;
    for (const char *verb : {"deck", "run", "sweep", "report", "compare"}) {
        EXPECT_EQ(printed([&] { return icacam::host::feCommand({verb, "--help"}); }), top) << verb;
        EXPECT_EQ(printed([&] { return icacam::host::feCommand({verb, "--k", "500", "-h"}); }), top) << verb;
    }
    EXPECT_THROW(icacam::host::feCommand({"run", "--bogus", "1"}), UsageError);
    EXPECT_THROW(icacam::host::feCommand({"run", "--k"}), UsageError);
    EXPECT_THROW(icacam::host::feCommand({"run", "--element", "CAX6"}), UsageError);
    EXPECT_THROW(icacam::host::feCommand({"frobnicate"}), UsageError);
    EXPECT_THROW(icacam::host::feCommand({}), UsageError);
}
