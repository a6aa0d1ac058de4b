#include "qr_filter.hpp"

#include <cmath>

namespace cosim::acceleration {

namespace {

// Gram-Schmidt of the `columns` of v in order; a column keeps when the
// norm left after orthogonalisation is at least `keep_fraction` of its own.
FilteredQR gram_schmidt(const Eigen::MatrixXd& v, const std::vector<std::size_t>& columns,
                        double keep_fraction) {
  FilteredQR out;
  const Eigen::Index n = static_cast<Eigen::Index>(columns.size());
  out.q.resize(v.rows(), n);
  out.r = Eigen::MatrixXd::Zero(n, n);
  Eigen::Index k = 0;
  for (std::size_t column : columns) {
    Eigen::VectorXd u = v.col(static_cast<Eigen::Index>(column));
    const double own = u.norm();
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(k);
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index j = 0; j < k; ++j) {
        const double c = out.q.col(j).dot(u);
        coefficients[j] += c;
        u -= c * out.q.col(j);
      }
    const double left = u.norm();
    if (!(own > 0.0) || !(left > keep_fraction * own)) continue;
    out.q.col(k) = u / left;
    out.r.col(k).head(k) = coefficients;
    out.r(k, k) = left;
    out.kept.push_back(column);
    ++k;
  }
  out.q.conservativeResize(Eigen::NoChange, k);
  out.r.conservativeResize(k, k);
  return out;
}

}  // namespace

FilteredQR filtered_qr(const Eigen::MatrixXd& v, Filter filter, double limit) {
  std::vector<std::size_t> columns(static_cast<std::size_t>(v.cols()));
  for (std::size_t i = 0; i < columns.size(); ++i) columns[i] = i;
  if (filter == Filter::qr2) return gram_schmidt(v, columns, limit);
  // Exactly dependent columns cannot be kept by any filter.
  constexpr double round_off = 1e-14;
  FilteredQR qr = gram_schmidt(v, columns, round_off);
  if (filter == Filter::none) return qr;
  for (;;) {
    const double frobenius = qr.r.norm();
    std::vector<std::size_t> kept;
    for (Eigen::Index i = 0; i < qr.r.rows(); ++i)
      if (std::abs(qr.r(i, i)) >= limit * frobenius) kept.push_back(qr.kept[i]);
    if (kept.size() == qr.kept.size()) return qr;
    qr = gram_schmidt(v, kept, round_off);
  }
}

}  // namespace cosim::acceleration
