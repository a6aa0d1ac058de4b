#include "acceleration/qr_filter.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <random>
#include <vector>

#include "acceleration_test_support.hpp"

namespace cosim::acceleration {
namespace {

Eigen::MatrixXd kept_columns(const Eigen::MatrixXd& v, const std::vector<std::size_t>& kept) {
  Eigen::MatrixXd columns(v.rows(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t j = 0; j < kept.size(); ++j)
    columns.col(static_cast<Eigen::Index>(j)) = v.col(static_cast<Eigen::Index>(kept[j]));
  return columns;
}

void expect_factorisation(const Eigen::MatrixXd& v, const FilteredQr& qr) {
  const auto kept = static_cast<Eigen::Index>(qr.kept.size());
  ASSERT_EQ(qr.q.cols(), kept);
  ASSERT_EQ(qr.r.rows(), kept);
  EXPECT_LE((qr.q.transpose() * qr.q - Eigen::MatrixXd::Identity(kept, kept)).norm(), 1e-14);
  EXPECT_LE((qr.q * qr.r - kept_columns(v, qr.kept)).norm(), 1e-14 * v.norm());
  EXPECT_TRUE(qr.r.isUpperTriangular());
}

TEST(QrFilter, FactorisesIndependentColumnsWithoutDroppingAny) {
  std::mt19937_64 rng(3);
  Eigen::MatrixXd v(20, 6);
  for (Eigen::Index j = 0; j < v.cols(); ++j) v.col(j) = testing::random_vector(20, rng);
  for (const Filter filter : {Filter::none, Filter::qr1, Filter::qr2}) {
    const FilteredQr qr = filtered_qr(v, filter, 1e-3);
    EXPECT_TRUE(qr.dropped.empty());
    expect_factorisation(v, qr);
  }
}

TEST(QrFilter, DropsADependentColumnAndKeepsTheNewest) {
  std::mt19937_64 rng(4);
  Eigen::MatrixXd v(8, 4);
  for (Eigen::Index j = 0; j < v.cols(); ++j) v.col(j) = testing::random_vector(8, rng);
  v.col(2) = 0.5 * v.col(0) - 2.0 * v.col(1) + 1e-9 * testing::random_vector(8, rng);
  for (const Filter filter : {Filter::qr1, Filter::qr2}) {
    const FilteredQr qr = filtered_qr(v, filter, 1e-6);
    EXPECT_EQ(qr.dropped, std::vector<std::size_t>{2});
    EXPECT_EQ(qr.kept, (std::vector<std::size_t>{0, 1, 3}));
    expect_factorisation(v, qr);
  }
  const FilteredQr unfiltered = filtered_qr(v, Filter::none, 1e-6);
  EXPECT_TRUE(unfiltered.dropped.empty());
}

// QR1 compares |R_ii| with ||R||_F, so a newest column much shorter than the
// others goes, however independent; QR2 compares each column with itself.
TEST(QrFilter, Qr1DropsAShortNewestColumnThatQr2Keeps) {
  std::mt19937_64 rng(5);
  Eigen::MatrixXd v(6, 3);
  for (Eigen::Index j = 0; j < v.cols(); ++j) v.col(j) = testing::random_vector(6, rng);
  v.col(0) *= 1e-4;
  EXPECT_EQ(filtered_qr(v, Filter::qr1, 1e-2).dropped, std::vector<std::size_t>{0});
  EXPECT_TRUE(filtered_qr(v, Filter::qr2, 1e-2).dropped.empty());
}

TEST(QrFilter, NeverKeepsMoreColumnsThanRowsOrAZeroColumn) {
  std::mt19937_64 rng(6);
  Eigen::MatrixXd v(3, 5);
  for (Eigen::Index j = 0; j < v.cols(); ++j) v.col(j) = testing::random_vector(3, rng);
  v.col(1).setZero();
  const FilteredQr qr = filtered_qr(v, Filter::none, 1e-2);
  EXPECT_EQ(qr.kept, (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(qr.dropped, (std::vector<std::size_t>{1, 4}));
  expect_factorisation(v, qr);
}

}  // namespace
}  // namespace cosim::acceleration
