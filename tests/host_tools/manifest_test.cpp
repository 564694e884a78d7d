#include <gtest/gtest.h>

#include "host_tools/manifest.h"

using namespace icacam::host;

TEST(Manifest, ParsesQuotedFieldsAndExtraColumns)
{
    Manifest m;
    std::string err;
    ASSERT_TRUE(
        parseManifest("id,image,n,mm_per_px,note\r\na,\"x,1.png\",0.2,0.01,\"he said \"\"hi\"\"\"\n\n", &m, &err));
    ASSERT_EQ(m.rows.size(), 1u);
    EXPECT_EQ(m.rows[0].get("image"), "x,1.png");
    EXPECT_EQ(m.rows[0].get("note"), "he said \"hi\"");
    EXPECT_EQ(m.rows[0].get("missing", "dflt"), "dflt");
}

TEST(Manifest, BadRowsAreRecordsWithAnError)
{
    Manifest m;
    std::string err;
    ASSERT_TRUE(parseManifest("id,image,n\na,b\nc,\"unterminated,1\nd,e,f\n", &m, &err));
    ASSERT_EQ(m.rows.size(), 3u);
    EXPECT_NE(m.rows[0].error.find("2 fields"), std::string::npos);
    EXPECT_NE(m.rows[1].error.find("quote"), std::string::npos);
    EXPECT_TRUE(m.rows[2].error.empty());
}

TEST(Manifest, NoHeaderOrNoIdIsAnError)
{
    Manifest m;
    std::string err;
    EXPECT_FALSE(parseManifest("", &m, &err));
    EXPECT_FALSE(parseManifest("image,n\nx,1\n", &m, &err));
    EXPECT_NE(err.find("id"), std::string::npos);
}

TEST(Manifest, NumbersAreStrict)
{
    double v;
    EXPECT_TRUE(parseNumber(" 0.25 ", &v));
    EXPECT_DOUBLE_EQ(v, 0.25);
    EXPECT_FALSE(parseNumber("0.25mm", &v));
    EXPECT_FALSE(parseNumber("nan", &v));
    EXPECT_FALSE(parseNumber("inf", &v));
    EXPECT_FALSE(parseNumber("", &v));
}
