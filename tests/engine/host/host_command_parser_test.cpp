#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/command_parser.h"

namespace nq {
namespace {

using Tokens = std::vector<std::string>;

std::vector<Tokens> tokens_of(std::string_view text) {
    std::vector<Tokens> out;
    for (const CommandArgs& args : parse_commands(text)) out.push_back(args.tokens());
    return out;
}

TEST(HostCommandParser, SplitsOnWhitespace) {
    EXPECT_EQ(tokens_of("  echo\thello   world  "),
              (std::vector<Tokens>{{"echo", "hello", "world"}}));
}

TEST(HostCommandParser, QuotedStringsAreOneTokenWithoutQuotes) {
    EXPECT_EQ(tokens_of("bind x \"say hi; there\""),
              (std::vector<Tokens>{{"bind", "x", "say hi; there"}}));
    EXPECT_EQ(tokens_of("echo \"\" a"), (std::vector<Tokens>{{"echo", "", "a"}}));
    // A closing quote ends the token; what follows starts the next one.
    EXPECT_EQ(tokens_of("\"abc\"def"), (std::vector<Tokens>{{"abc", "def"}}));
    // Inside a word a quote is an ordinary character.
    EXPECT_EQ(tokens_of("ab\"c"), (std::vector<Tokens>{{"ab\"c"}}));
}

TEST(HostCommandParser, SemicolonsAndNewlinesSeparateCommands) {
    EXPECT_EQ(tokens_of("a;b ; c\nd"), (std::vector<Tokens>{{"a"}, {"b"}, {"c"}, {"d"}}));
    EXPECT_EQ(tokens_of("echo a;;;echo b"), (std::vector<Tokens>{{"echo", "a"}, {"echo", "b"}}));
    EXPECT_EQ(tokens_of("echo \"a;b\";echo c"),
              (std::vector<Tokens>{{"echo", "a;b"}, {"echo", "c"}}));
}

TEST(HostCommandParser, CommentsRunToTheEndOfTheLine) {
    EXPECT_EQ(tokens_of("echo a // b; echo c\necho d"),
              (std::vector<Tokens>{{"echo", "a"}, {"echo", "d"}}));
    EXPECT_EQ(tokens_of("// only a comment"), std::vector<Tokens>{});
    EXPECT_EQ(tokens_of("echo a//b"), (std::vector<Tokens>{{"echo", "a//b"}}));
    EXPECT_EQ(tokens_of("connect http://host/x"),
              (std::vector<Tokens>{{"connect", "http://host/x"}}));
    EXPECT_EQ(tokens_of("echo \"// kept\""), (std::vector<Tokens>{{"echo", "// kept"}}));
}

TEST(HostCommandParser, EmptyLinesAndBlankCommandsAreSkipped) {
    EXPECT_EQ(tokens_of(""), std::vector<Tokens>{});
    EXPECT_EQ(tokens_of("\n\n   \n\t;\n"), std::vector<Tokens>{});
    EXPECT_EQ(tokens_of("\n\necho x\n\n"), (std::vector<Tokens>{{"echo", "x"}}));
}

TEST(HostCommandParser, UnterminatedQuoteEndsAtTheLine) {
    EXPECT_EQ(tokens_of("echo \"abc; def\necho g"),
              (std::vector<Tokens>{{"echo", "abc; def"}, {"echo", "g"}}));
}

TEST(HostCommandParser, WindowsLineEndings) {
    EXPECT_EQ(tokens_of("echo a\r\nbind \"b\" \"c\"\r\n"),
              (std::vector<Tokens>{{"echo", "a"}, {"bind", "b", "c"}}));
}

TEST(HostCommandParser, RawRestKeepsQuotesAndDropsComments) {
    ParsedCommand parsed = parse_next_command("  alias x echo \"a  b\"   // note\nnext");
    EXPECT_EQ(parsed.consumed, std::string("  alias x echo \"a  b\"   // note\n").size());
    const CommandArgs& args = parsed.args;
    ASSERT_EQ(args.argc(), 4u);
    EXPECT_EQ(args.name(), "alias");
    EXPECT_EQ(args.args(), "x echo \"a  b\"");
    EXPECT_EQ(args.rest(2), "echo \"a  b\"");
    EXPECT_EQ(args.rest(3), "\"a  b\"");
    EXPECT_EQ(args.rest(4), "");
    EXPECT_EQ(args.argv(3), "a  b");
    EXPECT_EQ(args.argv(9), "");
    EXPECT_EQ(args.value_from(3), "a  b");           // the last token: without its quotes
    EXPECT_EQ(args.value_from(2), "echo \"a  b\"");  // more: the raw rest
}

TEST(HostCommandParser, ConsumedStopsAfterTheSeparator) {
    EXPECT_EQ(parse_next_command("a b;c").consumed, 4u);
    EXPECT_EQ(parse_next_command("a b").consumed, 3u);
    EXPECT_EQ(parse_next_command(";").consumed, 1u);
    EXPECT_TRUE(parse_next_command(";").args.empty());
    EXPECT_EQ(parse_next_command("").consumed, 0u);
}

TEST(HostCommandParser, QuoteIfNeededReadsBackAsOneToken) {
    EXPECT_EQ(quote_if_needed("demo1"), "demo1");
    EXPECT_EQ(quote_if_needed(""), "\"\"");
    EXPECT_EQ(quote_if_needed("a b"), "\"a b\"");
    EXPECT_EQ(quote_if_needed("a;quit"), "\"a;quit\"");
    EXPECT_EQ(quote_if_needed("//x"), "\"//x\"");
    EXPECT_EQ(quote_if_needed("two\nlines"), "\"two lines\"");
    for (std::string token : {"a b", "x;y", "", "//c", "-1"}) {
        auto parsed = parse_commands("echo " + quote_if_needed(token));
        ASSERT_EQ(parsed.size(), 1u) << token;
        EXPECT_EQ(parsed[0].tokens(), (Tokens{"echo", token}));
    }
}

TEST(HostCommandParser, FromTokensBuildsRawText) {
    CommandArgs args = CommandArgs::from_tokens({"bind", "x", "say hi"});
    EXPECT_EQ(args.args(), "x \"say hi\"");
    EXPECT_EQ(args.value_from(2), "say hi");
}

}  // namespace
}  // namespace nq
