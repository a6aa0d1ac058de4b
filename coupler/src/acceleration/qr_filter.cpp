#include "qr_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cosim::acceleration {

namespace {

// A part orthogonal to the kept columns below this fraction of the column's
// norm is rounding error, not a direction.
constexpr double numerically_dependent = 64.0 * std::numeric_limits<double>::epsilon();

// Q and R grown one column at a time.
class GramSchmidtQr {
 public:
  GramSchmidtQr(Eigen::Index rows, Eigen::Index most_columns)
      : q_(rows, most_columns), r_(Eigen::MatrixXd::Zero(most_columns, most_columns)) {}

  // Appends column v unless its orthogonal part is below min_ratio ||v||;
  // returns whether it was appended.
  bool append(const Eigen::VectorXd& v, double min_ratio) {
    const double norm = v.norm();
    if (norm == 0.0 || kept_ == q_.rows()) return false;
    const auto basis = q_.leftCols(kept_);
    Eigen::VectorXd orthogonal = v;
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(kept_);
    for (int pass = 0; pass < 2; ++pass) {
      const Eigen::VectorXd projection = basis.transpose() * orthogonal;
      orthogonal -= basis * projection;
      coefficients += projection;
    }
    const double orthogonal_norm = orthogonal.norm();
    if (orthogonal_norm < min_ratio * norm) return false;
    q_.col(kept_) = orthogonal / orthogonal_norm;
    r_.col(kept_).head(kept_) = coefficients;
    r_(kept_, kept_) = orthogonal_norm;
    ++kept_;
    return true;
  }

  Eigen::MatrixXd q() const { return q_.leftCols(kept_); }
  Eigen::MatrixXd r() const { return r_.topLeftCorner(kept_, kept_); }

 private:
  Eigen::MatrixXd q_;
  Eigen::MatrixXd r_;
  Eigen::Index kept_ = 0;
};

// Factorises the given columns of v in order; `kept` receives those appended
// and `dropped` the others.
GramSchmidtQr factorise(const Eigen::MatrixXd& v, const std::vector<std::size_t>& columns,
                        double min_ratio, std::vector<std::size_t>& kept,
                        std::vector<std::size_t>& dropped) {
  GramSchmidtQr qr(v.rows(), static_cast<Eigen::Index>(columns.size()));
  kept.clear();
  for (const std::size_t c : columns) {
    if (qr.append(v.col(static_cast<Eigen::Index>(c)), min_ratio))
      kept.push_back(c);
    else
      dropped.push_back(c);
  }
  return qr;
}

}  // namespace

FilteredQr filtered_qr(const Eigen::MatrixXd& v, Filter filter, double limit) {
  std::vector<std::size_t> columns(static_cast<std::size_t>(v.cols()));
  std::iota(columns.begin(), columns.end(), std::size_t{0});
  std::vector<std::size_t> kept;
  std::vector<std::size_t> dropped;
  const double min_ratio =
      filter == Filter::qr2 ? std::max(limit, numerically_dependent) : numerically_dependent;
  GramSchmidtQr qr = factorise(v, columns, min_ratio, kept, dropped);

  if (filter == Filter::qr1) {
    for (;;) {
      const Eigen::MatrixXd r = qr.r();
      const double threshold = limit * r.norm();
      Eigen::Index below = 0;
      while (below < r.rows() && std::abs(r(below, below)) >= threshold) ++below;
      if (below == r.rows()) break;
      dropped.push_back(kept[static_cast<std::size_t>(below)]);
      kept.erase(kept.begin() + below);
      columns = kept;
      qr = factorise(v, columns, min_ratio, kept, dropped);
    }
  }

  std::sort(dropped.begin(), dropped.end());
  return {qr.q(), qr.r(), kept, dropped};
}

}  // namespace cosim::acceleration
