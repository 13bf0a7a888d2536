// Which cells of a design grid a point lies in: the guided search measures the grid's error there.
#include <gtest/gtest.h>

#include <vector>

#include "model/design/grid_guided_search.hpp"

namespace nibrig::model::design {
namespace {

// 3 fractions × 4 tips: 2 × 3 cells, numbered i * 3 + j.
const GridAxes kAxes{"vero", "DM85", {0.0, 0.5, 1.0}, {0.001, 0.002, 0.003, 0.004}};

using Cells = std::vector<std::size_t>;

TEST(GridCells, APointInsideACellIsInThatCellAlone) {
  EXPECT_EQ(grid_cells_at(kAxes, 0.25, 0.0015), Cells{0});
  EXPECT_EQ(grid_cells_at(kAxes, 0.75, 0.0035), Cells{5});
}

TEST(GridCells, APointOnAnEdgeOrANodeIsInEveryCellAroundIt) {
  EXPECT_EQ(grid_cells_at(kAxes, 0.5, 0.0015), (Cells{0, 3}));       // between two fractions' cells
  EXPECT_EQ(grid_cells_at(kAxes, 0.25, 0.002), (Cells{0, 1}));       // between two tips' cells
  EXPECT_EQ(grid_cells_at(kAxes, 0.5, 0.003), (Cells{1, 2, 4, 5}));  // an inner node
  EXPECT_EQ(grid_cells_at(kAxes, 0.0, 0.001), Cells{0});             // a corner
  // A search's arithmetic lands a rounding away from a node: still on it.
  EXPECT_EQ(grid_cells_at(kAxes, 0.5 + 1e-15, 0.0015), (Cells{0, 3}));
}

TEST(GridCells, APointOutsideTheGridIsInNoCell) {
  EXPECT_TRUE(grid_cells_at(kAxes, 1.1, 0.002).empty());
  EXPECT_TRUE(grid_cells_at(kAxes, 0.5, 0.0045).empty());
}

}  // namespace
}  // namespace nibrig::model::design
