// What `mdltool adjacency` prints per model and in total: a fixed-width table (optionally with
// timings) or JSON.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "adjacency/paper_baseline.h"
#include "adjacency/recovery_stats.h"
#include "adjacency/verdict.h"
#include "common/json_writer.h"

namespace nq::mdltool {

struct ModelReport {
    std::string name;
    npr::adjacency::RecoveryStats stats;
    npr::adjacency::BaselineReport paper;
    npr::adjacency::Verdict verdict;
    std::vector<std::string> problems;  // failed consistency checks (empty = all passed)
};

struct AdjacencyTotals {
    size_t models = 0, true_edges = 0, checks_failed = 0;
    uint64_t triangles = 0, degenerate = 0, duplicates = 0, welds = 0, kept_apart = 0;
    uint64_t flipped = 0, splits = 0, poses = 0;
    npr::adjacency::EdgeCensus soup, mesh, paper_first_pose;
    double recovery_seconds = 0.0, paper_seconds = 0.0;

    void add(const ModelReport& report);
};

void print_table_header(std::ostream& out, bool timing);
void print_table_row(std::ostream& out, const ModelReport& report, bool timing);
void print_totals(std::ostream& out, const AdjacencyTotals& totals, bool timing);
void print_legend(std::ostream& out);

void write_model_json(JsonWriter& json, const ModelReport& report);
void write_totals_json(JsonWriter& json, const AdjacencyTotals& totals);

}  // namespace nq::mdltool
