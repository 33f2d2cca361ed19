#include "obscurance/sample_tables.h"

namespace nq::npr::obscurance {

namespace {

// Written by vo_samples --format cpp; each file starts with the command that made it.
#include "obscurance/tables/electrostatic_lines_5.inc"
#include "obscurance/tables/electrostatic_lines_9.inc"
#include "obscurance/tables/electrostatic_points_12.inc"
#include "obscurance/tables/electrostatic_points_33.inc"
// The paper's counts' neighbours, electrostatic only: for checking that 5, 9, 12 and 33 beat them.
#include "obscurance/tables/electrostatic_lines_10.inc"
#include "obscurance/tables/electrostatic_lines_4.inc"
#include "obscurance/tables/electrostatic_lines_6.inc"
#include "obscurance/tables/electrostatic_lines_8.inc"
#include "obscurance/tables/electrostatic_points_11.inc"
#include "obscurance/tables/electrostatic_points_13.inc"
#include "obscurance/tables/electrostatic_points_32.inc"
#include "obscurance/tables/electrostatic_points_34.inc"
#include "obscurance/tables/lloyd_lines_5.inc"
#include "obscurance/tables/lloyd_lines_9.inc"
#include "obscurance/tables/lloyd_points_12.inc"
#include "obscurance/tables/lloyd_points_33.inc"
#include "obscurance/tables/poisson_lines_5.inc"
#include "obscurance/tables/poisson_lines_9.inc"
#include "obscurance/tables/poisson_points_12.inc"
#include "obscurance/tables/poisson_points_33.inc"

template <class Row>
struct TableEntry {
    SampleMethod method;
    std::span<const Row> rows;
};

constexpr TableEntry<LineSampleRow> kLineTables[] = {
    {SampleMethod::electrostatic, kElectrostaticLines5},
    {SampleMethod::electrostatic, kElectrostaticLines9},
    {SampleMethod::electrostatic, kElectrostaticLines4},
    {SampleMethod::electrostatic, kElectrostaticLines6},
    {SampleMethod::electrostatic, kElectrostaticLines8},
    {SampleMethod::electrostatic, kElectrostaticLines10},
    {SampleMethod::lloyd, kLloydLines5},
    {SampleMethod::lloyd, kLloydLines9},
    {SampleMethod::poisson, kPoissonLines5},
    {SampleMethod::poisson, kPoissonLines9},
};

constexpr TableEntry<PointSampleRow> kPointTables[] = {
    {SampleMethod::electrostatic, kElectrostaticPoints12},
    {SampleMethod::electrostatic, kElectrostaticPoints33},
    {SampleMethod::electrostatic, kElectrostaticPoints11},
    {SampleMethod::electrostatic, kElectrostaticPoints13},
    {SampleMethod::electrostatic, kElectrostaticPoints32},
    {SampleMethod::electrostatic, kElectrostaticPoints34},
    {SampleMethod::lloyd, kLloydPoints12},
    {SampleMethod::lloyd, kLloydPoints33},
    {SampleMethod::poisson, kPoissonPoints12},
    {SampleMethod::poisson, kPoissonPoints33},
};

template <class Row>
std::span<const Row> find_table(std::span<const TableEntry<Row>> tables, SampleMethod method,
                                int count) {
    for (const TableEntry<Row>& table : tables) {
        if (table.method == method && static_cast<int>(table.rows.size()) == count) {
            return table.rows;
        }
    }
    return {};
}

}  // namespace

std::span<const LineSampleRow> line_sample_table(SampleMethod method, int count) {
    return find_table<LineSampleRow>(kLineTables, method, count);
}

std::span<const PointSampleRow> point_sample_table(SampleMethod method, int count) {
    return find_table<PointSampleRow>(kPointTables, method, count);
}

LineSampleSet to_sample_set(std::span<const LineSampleRow> rows) {
    LineSampleSet set;
    for (const LineSampleRow& row : rows) {
        set.positions.push_back({row.x, row.y});
        set.weights.push_back(row.weight);
    }
    return set;
}

PointSampleSet to_sample_set(std::span<const PointSampleRow> rows) {
    PointSampleSet set;
    for (const PointSampleRow& row : rows) {
        set.positions.push_back({row.x, row.y, row.z});
        set.weights.push_back(row.weight);
    }
    return set;
}

}  // namespace nq::npr::obscurance
