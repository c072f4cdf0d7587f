#include "pmdplan/planning/connect_tree.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace pmdplan {
namespace {

Eigen::VectorXd point(double x, double y) { return Eigen::Vector2d(x, y); }

/// root (0) - a (1) - b (2) - c (3), and root - d (4).
ConnectTree chainAndBranch() {
  ConnectTree tree;
  tree.add(point(0, 0), point(0, 0), ConnectTree::kNoParent);
  tree.add(point(1, 0), point(1, 0), 0);
  tree.add(point(2, 0), point(2, 0), 1);
  tree.add(point(3, 0), point(3, 0), 2);
  tree.add(point(0, 1), point(0, 1), 0);
  return tree;
}

TEST(ConnectTree, NearestIsTheClosestLiveNodeAndTiesGoToTheLowerIndex) {
  ConnectTree tree = chainAndBranch();
  EXPECT_EQ(tree.nearest(point(2.2, 0.1)), 2u);
  EXPECT_EQ(tree.nearest(point(0.5, 0.0)), 0u) << "equally far from 0 and 1";
  EXPECT_EQ(tree.nearest(point(0.1, 0.9)), 4u);
}

TEST(ConnectTree, BranchRunsFromTheNodeToTheRoot) {
  const ConnectTree tree = chainAndBranch();
  EXPECT_EQ(tree.branch(3), (std::vector<ConnectTree::Node>{3, 2, 1, 0}));
  EXPECT_EQ(tree.branch(4), (std::vector<ConnectTree::Node>{4, 0}));
  EXPECT_EQ(tree.branch(0), (std::vector<ConnectTree::Node>{0}));
}

TEST(ConnectTree, SegmentsStartUncheckedAndTheRootHasNone) {
  ConnectTree tree = chainAndBranch();
  EXPECT_TRUE(tree.segmentChecked(0));
  EXPECT_FALSE(tree.segmentChecked(2));
  tree.markSegmentFree(2);
  EXPECT_TRUE(tree.segmentChecked(2));
  EXPECT_FALSE(tree.segmentChecked(3));
}

TEST(ConnectTree, CuttingANodeCutsEverythingBelowItOnly) {
  ConnectTree tree = chainAndBranch();
  tree.add(point(2, 1), point(2, 1), 2);  // 5, below b
  tree.cut(2);
  EXPECT_TRUE(tree.isLive(0));
  EXPECT_TRUE(tree.isLive(1));
  EXPECT_FALSE(tree.isLive(2));
  EXPECT_FALSE(tree.isLive(3));
  EXPECT_TRUE(tree.isLive(4));
  EXPECT_FALSE(tree.isLive(5));
  EXPECT_EQ(tree.liveCount(), 3u);
  EXPECT_EQ(tree.size(), 6u);
  EXPECT_EQ(tree.nearest(point(3, 0)), 1u) << "cut nodes are never nearest";
  EXPECT_THROW(tree.add(point(4, 0), point(4, 0), 3), std::invalid_argument) << "no child of a cut node";
  EXPECT_THROW(tree.cut(0), std::invalid_argument) << "the root stays";
}

TEST(ConnectTree, MalformedNodesAreRefused) {
  ConnectTree tree;
  EXPECT_THROW(tree.nearest(point(0, 0)), std::logic_error);
  EXPECT_THROW(tree.add(point(0, 0), point(0, 0), 0), std::invalid_argument) << "a root has no parent";
  tree.add(point(0, 0), point(0, 0), ConnectTree::kNoParent);
  EXPECT_THROW(tree.add(point(1, 0), Eigen::Vector3d(1, 0, 0), 0), std::invalid_argument);
  EXPECT_THROW(tree.add(point(1, 0), point(1, 0), 7), std::invalid_argument);
  tree.clear();
  EXPECT_EQ(tree.size(), 0u);
  EXPECT_EQ(tree.liveCount(), 0u);
}

}  // namespace
}  // namespace pmdplan
