// The console's text side: wrapping, the scrollback ring, notify rows, the centre-screen
// message and the screen layout arithmetic.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "console/center_print.h"
#include "console/console_layout.h"
#include "console/console_text.h"
#include "console/text_wrap.h"

namespace nq {
namespace {

std::vector<std::string> rows_of(std::string_view line, size_t columns) {
    std::vector<std::string> rows;
    WrappedRow row = wrap_row(line, 0, columns);
    while (true) {
        rows.emplace_back(line.substr(row.begin, row.end - row.begin));
        if (row.next >= line.size()) break;
        row = wrap_row(line, row.next, columns);
    }
    return rows;
}

std::vector<std::string> visible(const ConsoleText& text, size_t count) {
    std::vector<std::string_view> views(count);
    size_t filled = text.visible_rows(views);
    return std::vector<std::string>(views.begin(), views.begin() + static_cast<long>(filled));
}

std::vector<std::string> notify(const ConsoleText& text, double now, double seconds) {
    std::array<std::string_view, 4> views;
    size_t filled = text.notify_rows(now, seconds, views);
    return std::vector<std::string>(views.begin(), views.begin() + static_cast<long>(filled));
}

using Rows = std::vector<std::string>;

TEST(ConsoleWrap, BreaksBetweenWords) {
    EXPECT_EQ(rows_of("hello world", 8), (Rows{"hello", "world"}));
    EXPECT_EQ(rows_of("one two three four", 9), (Rows{"one two", "three", "four"}));
    EXPECT_EQ(wrapped_row_count("one two three four", 9), 3u);
}

TEST(ConsoleWrap, CutsWordsLongerThanARow) {
    EXPECT_EQ(rows_of("abcdefghij", 4), (Rows{"abcd", "efgh", "ij"}));
}

TEST(ConsoleWrap, ExactFitAndBreakRightAfterAFullRow) {
    EXPECT_EQ(rows_of("abcd", 4), (Rows{"abcd"}));
    // The space right after a full row is the break: no empty row, no leading space.
    EXPECT_EQ(rows_of("abcd efgh", 4), (Rows{"abcd", "efgh"}));
}

TEST(ConsoleWrap, ColouredSpaceIsASpace) {
    std::string line =
        "ab\xA0"
        "cd";  // 0xA0: a space from the alternate font half
    EXPECT_EQ(rows_of(line, 3), (Rows{"ab", "cd"}));
}

TEST(ConsoleWrap, EmptyLineIsOneRow) {
    EXPECT_EQ(wrapped_row_count("", 10), 1u);
    EXPECT_EQ(rows_of("", 10), (Rows{""}));
}

TEST(ConsoleText, LinesEndAtNewlinesAndPiecesJoin) {
    ConsoleText text;
    text.print("abc", 0);
    text.print("def\nsecond\n", 0);
    ASSERT_EQ(text.line_count(), 2u);
    EXPECT_EQ(text.line(0), "second");
    EXPECT_EQ(text.line(1), "abcdef");
    // After a finished line, "\n" alone is an empty line (as Quake prints blank lines).
    text.print("\n", 0);
    ASSERT_EQ(text.line_count(), 3u);
    EXPECT_EQ(text.line(0), "");
}

TEST(ConsoleText, RingDropsTheOldestLines) {
    ConsoleText text(4);
    for (int i = 0; i < 6; ++i) text.print("L" + std::to_string(i) + "\n", 0);
    ASSERT_EQ(text.line_count(), 4u);
    EXPECT_EQ(text.line(0), "L5");
    EXPECT_EQ(text.line(3), "L2");  // L0 and L1 are gone
    EXPECT_EQ(visible(text, 10), (Rows{"L5", "L4", "L3", "L2"}));
}

TEST(ConsoleText, RawBytesAndColourMarker) {
    ConsoleText text;
    text.print("plain \xC1\n", 0);  // bit 7 set: kept as is
    EXPECT_EQ(text.line(0), "plain \xC1");
    text.print("\x02hi there\n", 0);  // whole message in the alternate half, marker dropped
    EXPECT_EQ(text.line(0), std::string("\xE8\xE9\xA0\xF4\xE8\xE5\xF2\xE5"));
    text.print("a\tb\r\n", 0);
    EXPECT_EQ(text.line(0), "a b");
}

TEST(ConsoleText, OverlongLineContinuesOnANewLine) {
    ConsoleText text;
    text.print(std::string(kMaxConsoleLineBytes + 10, 'x') + "\n", 0);
    ASSERT_EQ(text.line_count(), 2u);
    EXPECT_EQ(text.line(1).size(), kMaxConsoleLineBytes);
    EXPECT_EQ(text.line(0).size(), 10u);
}

TEST(ConsoleText, VisibleRowsWrapAtTheColumns) {
    ConsoleText text;
    text.set_columns(5);
    text.print("first\nhello world again\n", 0);
    EXPECT_EQ(text.total_rows(), 4u);
    EXPECT_EQ(visible(text, 10), (Rows{"again", "world", "hello", "first"}));
    EXPECT_EQ(visible(text, 2), (Rows{"again", "world"}));
    // A resize re-wraps what is stored.
    text.set_columns(11);
    EXPECT_EQ(visible(text, 10), (Rows{"again", "hello world", "first"}));
}

TEST(ConsoleText, ScrollbackMovesTheWindowAndClamps) {
    ConsoleText text;
    for (int i = 0; i < 10; ++i) text.print("L" + std::to_string(i) + "\n", 0);
    text.scroll(3);
    EXPECT_EQ(text.scroll_rows(), 3u);
    EXPECT_EQ(visible(text, 2), (Rows{"L6", "L5"}));
    text.scroll(100);
    EXPECT_EQ(text.scroll_rows(), 9u);  // the oldest row stays on screen
    EXPECT_EQ(visible(text, 3), (Rows{"L0"}));
    text.scroll(-4);
    EXPECT_EQ(visible(text, 1), (Rows{"L4"}));
    text.scroll(-100);
    EXPECT_EQ(text.scroll_rows(), 0u);
    text.scroll_to_top();
    EXPECT_EQ(text.scroll_rows(), 9u);
}

TEST(ConsoleText, ScrollSkipsWrappedRowsOfOneLine) {
    ConsoleText text;
    text.set_columns(5);
    text.print("older\naaaaa bbbbb ccccc\n", 0);
    text.scroll(1);
    EXPECT_EQ(visible(text, 3), (Rows{"bbbbb", "aaaaa", "older"}));
}

TEST(ConsoleText, ClearEmptiesEverything) {
    ConsoleText text;
    text.print("a\nb\n", 0);
    text.clear();
    EXPECT_EQ(text.line_count(), 0u);
    EXPECT_EQ(text.total_rows(), 0u);
    EXPECT_TRUE(visible(text, 4).empty());
    text.print("c\n", 0);
    EXPECT_EQ(visible(text, 4), (Rows{"c"}));
}

TEST(ConsoleNotify, ShowsRecentLinesUntilTheyExpire) {
    ConsoleText text;
    text.print("a\n", 0.0);
    text.print("b\n", 1.0);
    text.print("c\n", 2.5);
    EXPECT_EQ(notify(text, 2.9, 3.0), (Rows{"c", "b", "a"}));
    EXPECT_EQ(notify(text, 3.2, 3.0), (Rows{"c", "b"}));  // "a" was printed 3.2 s ago
    EXPECT_EQ(notify(text, 5.4, 3.0), (Rows{"c"}));
    EXPECT_TRUE(notify(text, 5.6, 3.0).empty());
    EXPECT_TRUE(notify(text, 2.9, 0.0).empty());  // con_notifytime 0: none
}

TEST(ConsoleNotify, AtMostFourRowsNewestFirst) {
    ConsoleText text;
    text.set_columns(5);
    for (int i = 0; i < 6; ++i) text.print("L" + std::to_string(i) + "\n", 0);
    EXPECT_EQ(notify(text, 0.5, 3), (Rows{"L5", "L4", "L3", "L2"}));
    // Rows, not lines: a wrapped line takes several.
    text.print("aaaaa bbbbb ccccc\n", 0);
    EXPECT_EQ(notify(text, 0.5, 3), (Rows{"ccccc", "bbbbb", "aaaaa", "L5"}));
}

TEST(ConsoleNotify, ClearNotifyHidesPrintedLines) {
    ConsoleText text;
    text.print("a\nb\n", 1.0);
    text.clear_notify();
    EXPECT_TRUE(notify(text, 1.5, 3).empty());
    text.print("c\n", 1.5);
    EXPECT_EQ(notify(text, 1.5, 3), (Rows{"c"}));
}

TEST(CenterPrint, ShowsForItsTimeOnly) {
    CenterPrint center;
    EXPECT_FALSE(center.visible(0, 2));
    center.show("The door is locked", 10.0);
    EXPECT_FALSE(center.visible(9.9, 2.0));
    EXPECT_TRUE(center.visible(10.0, 2.0));
    EXPECT_TRUE(center.visible(11.99, 2.0));
    EXPECT_FALSE(center.visible(12.0, 2.0));
    center.show("again", 20.0);  // a new message restarts the clock
    EXPECT_TRUE(center.visible(21.0, 2.0));
    EXPECT_EQ(center.text(), "again");
    center.show("", 30.0);
    EXPECT_FALSE(center.visible(30.5, 2.0));
}

TEST(CenterPrint, SplitsLinesAtNewlinesAndFortyColumns) {
    CenterPrint center;
    std::string long_line(45, 'x');
    center.show("short\n" + long_line + "\n\nend\n", 0);
    std::array<std::string_view, 8> lines;
    ASSERT_EQ(center.lines(lines), 5u);
    EXPECT_EQ(center.line_count(), 5u);
    EXPECT_EQ(lines[0], "short");
    EXPECT_EQ(lines[1], std::string(40, 'x'));
    EXPECT_EQ(lines[2], std::string(5, 'x'));
    EXPECT_EQ(lines[3], "");
    EXPECT_EQ(lines[4], "end");  // the trailing newline adds no empty line
    std::array<std::string_view, 2> few;
    EXPECT_EQ(center.lines(few), 2u);
}

TEST(ConsoleLayout, ScalesWholeMultiplesOfTheQuakeScreen) {
    ConsoleLayout small = make_console_layout(640, 480, 0);
    EXPECT_EQ(small.scale, 1);
    EXPECT_EQ(small.cell, 8);
    EXPECT_EQ(small.columns, 78u);  // Quake: (640 >> 3) - 2

    ConsoleLayout hd = make_console_layout(1920, 1080, 0);
    EXPECT_EQ(hd.scale, 2);  // 1080 / 480 = 2 limits it, not 1920 / 640 = 3
    EXPECT_EQ(hd.columns, 1920u / 16 - 2);

    EXPECT_EQ(make_console_layout(1920, 1080, 3).scale, 3);
    EXPECT_EQ(make_console_layout(64, 48, 0).scale, 1);  // never below 1
    EXPECT_EQ(make_console_layout(8, 8, 0).columns, 1u);
}

TEST(ConsoleLayout, RowsAboveTheInputLine) {
    ConsoleLayout layout = make_console_layout(640, 480, 1);
    // Console 240 pixels tall: input line at 224, newest text row at 224 - 12 = 212.
    EXPECT_EQ(layout.input_row_top(240), 224);
    EXPECT_EQ(layout.newest_text_row_top(240), 212);
    EXPECT_EQ(layout.text_rows(240), 212 / 8 + 1);
    EXPECT_EQ(layout.text_rows(10), 0);
}

}  // namespace
}  // namespace nq
