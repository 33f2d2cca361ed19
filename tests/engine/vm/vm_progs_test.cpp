// progs.dat loading: the real LibreQuake progs against its own header bytes, and every malformed
// case the loader must reject with the file, the byte offset and the problem.
#include <gtest/gtest.h>

#include <cstring>

#include "common/file_io.h"
#include "support/synth_progs.h"
#include "support/test_data.h"
#include "vm/opcodes.h"
#include "vm/progs.h"

namespace nq::vm {
namespace {

using test::SynthProgs;

int32_t header_word(const std::vector<uint8_t>& bytes, int i) {
    int32_t v;
    std::memcpy(&v, bytes.data() + i * 4, 4);
    return v;
}

// main: c = a + b; return
SynthProgs small_program() {
    SynthProgs p;
    const uint16_t a = p.global(2), b = p.global(3), c = p.global_vector(0, 0, 0);
    p.function("main");
    p.op(kOpAddF, a, b, c);
    p.op(kOpReturn, c);
    return p;
}

Error parse_error(const SynthProgs& p) {
    auto progs = parse_progs(p.bytes(), "bad.dat");
    EXPECT_FALSE(progs.ok());
    if (progs.ok()) return {};
    EXPECT_EQ(progs.error().file, "bad.dat");
    return progs.error();
}

TEST(VmProgs, RealProgsMatchesItsHeader) {
    const std::string path = test::lq1_dir() + "/progs.dat";
    auto bytes = read_file(path);
    ASSERT_TRUE(bytes) << path;
    auto progs = parse_progs(*bytes, path);
    ASSERT_TRUE(progs) << progs.error().to_string();
    EXPECT_EQ(header_word(*bytes, 0), kProgsVersion);
    EXPECT_EQ(progs->crc, header_word(*bytes, 1));
    EXPECT_EQ(progs->statements.size(), size_t(header_word(*bytes, 3)));
    EXPECT_EQ(progs->global_defs.size(), size_t(header_word(*bytes, 5)));
    EXPECT_EQ(progs->field_defs.size(), size_t(header_word(*bytes, 7)));
    EXPECT_EQ(progs->functions.size(), size_t(header_word(*bytes, 9)));
    EXPECT_EQ(progs->globals.size(), size_t(header_word(*bytes, 13)));
    EXPECT_EQ(progs->entity_fields, uint32_t(header_word(*bytes, 14)));
    // The game's entry points and the standard system fields are there by name.
    for (const char* f : {"main", "StartFrame", "PlayerPreThink", "PlayerPostThink",
                          "ClientConnect", "PutClientInServer", "worldspawn"}) {
        EXPECT_GT(progs->find_function(f), 0) << f;
    }
    for (const char* f : {"origin", "velocity", "health", "think", "nextthink", "touch"}) {
        EXPECT_NE(progs->find_field(f), nullptr) << f;
    }
    EXPECT_NE(progs->find_global("self"), nullptr);
    // The first global definition's name is read from the raw string table.
    const int32_t strings_at = header_word(*bytes, 10);
    const Def& first = progs->global_defs.at(1);
    EXPECT_EQ(progs->string_at(first.name),
              std::string(reinterpret_cast<const char*>(bytes->data() + strings_at + first.name)));
}

TEST(VmProgs, SmallProgramLoads) {
    auto progs = parse_progs(small_program().bytes(), "small.dat");
    ASSERT_TRUE(progs) << progs.error().to_string();
    EXPECT_EQ(progs->functions.size(), 2u);
    EXPECT_EQ(progs->find_function("main"), 1);
    EXPECT_EQ(progs->statements.at(0).op, kOpAddF);
}

TEST(VmProgs, TruncatedFilesFailWithTheirOffset) {
    const std::vector<uint8_t> bytes = small_program().bytes();
    for (size_t n : {size_t(0), size_t(10), kProgsHeaderBytes, bytes.size() - 1}) {
        std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + long(n));
        auto progs = parse_progs(cut, "cut.dat");
        ASSERT_FALSE(progs) << n;
        EXPECT_EQ(progs.error().file, "cut.dat");
        EXPECT_FALSE(progs.error().message.empty());
    }
}

TEST(VmProgs, WrongVersionIsRejected) {
    SynthProgs p = small_program();
    p.version = 7;
    EXPECT_NE(parse_error(p).message.find("version 7"), std::string::npos);
}

TEST(VmProgs, LyingCountsAreRejected) {
    SynthProgs p = small_program();
    p.num_statements = 1 << 28;
    EXPECT_NE(parse_error(p).message.find("statements"), std::string::npos);
    SynthProgs q = small_program();
    q.num_globals = -1;
    EXPECT_NE(parse_error(q).message.find("negative"), std::string::npos);
    SynthProgs r = small_program();
    r.ofs_functions = 1 << 30;
    EXPECT_NE(parse_error(r).message.find("functions"), std::string::npos);
}

TEST(VmProgs, UnknownOpcodeNamesTheStatement) {
    SynthProgs p = small_program();
    p.op(200);
    const Error e = parse_error(p);
    EXPECT_NE(e.message.find("statement 2"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("opcode 200"), std::string::npos) << e.message;
    EXPECT_EQ(e.offset, kProgsHeaderBytes + 2 * 8);
}

TEST(VmProgs, OperandsOutsideTheGlobalsAreRejected) {
    SynthProgs p = small_program();
    p.op(kOpAddF, 0, 0, 60000);
    EXPECT_NE(parse_error(p).message.find("operand c"), std::string::npos);
    // A vector operand needs three words: the last global is not enough.
    SynthProgs q = small_program();
    q.op(kOpStoreV, 0, uint16_t(q.globals.size() - 1));
    EXPECT_NE(parse_error(q).message.find("operand b"), std::string::npos);
}

TEST(VmProgs, JumpsOutsideTheCodeAreRejected) {
    SynthProgs p = small_program();
    p.op(kOpGoto, uint16_t(-10));
    EXPECT_NE(parse_error(p).message.find("jumps to statement -8"), std::string::npos);
    SynthProgs q = small_program();
    q.op(kOpIf, 0, 5);
    EXPECT_NE(parse_error(q).message.find("jumps"), std::string::npos);
}

TEST(VmProgs, BadFunctionsAreRejected) {
    SynthProgs p = small_program();
    p.functions[1].first_statement = 99;
    EXPECT_NE(parse_error(p).message.find("starts at statement 99"), std::string::npos);
    SynthProgs q = small_program();
    q.functions[1].parm_start = int32_t(q.globals.size());
    q.functions[1].locals = 4;
    EXPECT_NE(parse_error(q).message.find("locals"), std::string::npos);
    SynthProgs r = small_program();
    r.functions[1].num_parms = 9;
    EXPECT_NE(parse_error(r).message.find("9 parameters"), std::string::npos);
    SynthProgs s = small_program();
    s.functions[1].name = 1 << 20;
    EXPECT_NE(parse_error(s).message.find("outside the"), std::string::npos);
}

TEST(VmProgs, DefinitionsOutsideTheirSpaceAreRejected) {
    SynthProgs p = small_program();
    p.name_global("far", uint16_t(DefType::vector), uint16_t(p.globals.size() - 2));
    EXPECT_NE(parse_error(p).message.find("far"), std::string::npos);
    SynthProgs q = small_program();
    q.field("origin", uint16_t(DefType::vector), 3);
    q.entity_fields = 2;
    EXPECT_NE(parse_error(q).message.find("field definition"), std::string::npos);
}

TEST(VmProgs, UnterminatedStringTableStillReadsSafely) {
    SynthProgs p = small_program();
    p.strings += "tail-without-nul";
    auto progs = parse_progs(p.bytes(), "tail.dat");
    ASSERT_TRUE(progs) << progs.error().to_string();
    EXPECT_EQ(progs->strings.back(), '\0');
    EXPECT_EQ(progs->string_at(int32_t(p.strings.size()) - 16), "tail-without-nul");
    EXPECT_EQ(progs->string_at(int32_t(p.strings.size()) + 5), "");
}

}  // namespace
}  // namespace nq::vm
