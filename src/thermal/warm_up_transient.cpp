#include "imu_lab/thermal/warm_up_transient.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "imu_lab/common/ceres_solver_options.h"

namespace imu_lab {
namespace thermal {
namespace {

constexpr int kTimeConstantGrid = 24;     // log-spaced start values per time constant
constexpr std::size_t kSpareBlocks = 10;  // blocks beyond the largest model's parameter count

// The average of e^{-t/T} over [t0, t1] and its derivative in T. Written with expm1 so that a
// block much shorter than T keeps its digits.
struct ExponentialAverage {
  double value = 0.0;
  double derivative = 0.0;  // d value / d T
};

ExponentialAverage exponential_average(double t0_s, double t1_s, double time_constant_s) {
  const double start = std::exp(-t0_s / time_constant_s);
  const double width_s = t1_s - t0_s;
  ExponentialAverage result;
  if (width_s <= 1e-12 * time_constant_s) {
    result.value = start;
    result.derivative = start * t0_s / (time_constant_s * time_constant_s);
    return result;
  }
  const double x = width_s / time_constant_s;
  const double decayed = -std::expm1(-x);  // 1 - e^{-x}
  result.value = start * decayed / x;
  result.derivative =
      start / width_s * (decayed - x * std::exp(-x)) + result.value * t0_s / (time_constant_s * time_constant_s);
  return result;
}

// Parameters (c, a_1, T_1, ..., a_K, T_K).
double block_model(const WarmUpBlock& block, const double* parameters, int terms) {
  double value = parameters[0];
  for (int k = 0; k < terms; ++k) {
    value += parameters[1 + 2 * k] * exponential_average(block.start_s, block.end_s, parameters[2 + 2 * k]).value;
  }
  return value;
}

// d model / d parameters for one block.
void block_gradient(const WarmUpBlock& block, const double* parameters, int terms, double* gradient) {
  gradient[0] = 1.0;
  for (int k = 0; k < terms; ++k) {
    const ExponentialAverage e = exponential_average(block.start_s, block.end_s, parameters[2 + 2 * k]);
    gradient[1 + 2 * k] = e.value;
    gradient[2 + 2 * k] = parameters[1 + 2 * k] * e.derivative;
  }
}

// Weighted residuals sqrt(w_i) (mean_i - model_i) of every block, w_i = count_i / mean count.
class WarmUpCost : public ceres::CostFunction {
 public:
  WarmUpCost(const std::vector<WarmUpBlock>& blocks, const std::vector<double>& root_weights, int terms)
      : blocks_(blocks), root_weights_(root_weights), terms_(terms) {
    set_num_residuals(static_cast<int>(blocks.size()));
    mutable_parameter_block_sizes()->push_back(1 + 2 * terms);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const int size = 1 + 2 * terms_;
    std::vector<double> gradient(size);
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      residuals[i] = root_weights_[i] * (blocks_[i].mean - block_model(blocks_[i], parameters[0], terms_));
      if (!std::isfinite(residuals[i])) return false;
      if (jacobians != nullptr && jacobians[0] != nullptr) {
        block_gradient(blocks_[i], parameters[0], terms_, gradient.data());
        for (int p = 0; p < size; ++p) jacobians[0][i * size + p] = -root_weights_[i] * gradient[p];
      }
    }
    return true;
  }

 private:
  const std::vector<WarmUpBlock>& blocks_;
  const std::vector<double>& root_weights_;
  int terms_;
};

struct Solution {
  std::vector<double> parameters;  // (c, a_1, T_1, ...)
  double residual_sum_of_squares = std::numeric_limits<double>::infinity();
  bool usable = false;
};

// Weighted linear least squares of the block means on the given columns (the amplitudes and c
// for fixed time constants); returns the coefficients and the residual sum of squares.
double linear_fit(const Eigen::MatrixXd& columns, const Eigen::VectorXd& target, Eigen::VectorXd* coefficients) {
  *coefficients = columns.colPivHouseholderQr().solve(target);
  return (target - columns * *coefficients).squaredNorm();
}

class WarmUpFitter {
 public:
  WarmUpFitter(const std::vector<WarmUpBlock>& blocks, double block_s, const WarmUpFitOptions& options)
      : blocks_(blocks), options_(options) {
    double mean_count = 0.0;
    for (const WarmUpBlock& block : blocks) mean_count += static_cast<double>(block.count);
    mean_count /= static_cast<double>(blocks.size());
    target_.resize(static_cast<Eigen::Index>(blocks.size()));
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      root_weights_.push_back(std::sqrt(static_cast<double>(blocks[i].count) / mean_count));
      target_[static_cast<Eigen::Index>(i)] = root_weights_[i] * blocks[i].mean;
    }
    lowest_s_ = options.min_time_constant_blocks * block_s;
    highest_s_ = options.max_time_constant_records * std::max(blocks.back().end_s, block_s);
    for (int g = 0; g < kTimeConstantGrid; ++g) {
      grid_s_.push_back(lowest_s_ * std::pow(highest_s_ / lowest_s_, (g + 0.5) / kTimeConstantGrid));
    }
    const Eigen::MatrixXd grid_columns = columns(grid_s_);
    grid_gram_ = grid_columns.transpose() * grid_columns;
    grid_projection_ = grid_columns.transpose() * target_;
  }

  // The best fit with `terms` exponentials: the grid's best linear fit (from the Gram matrix of
  // the constant and every grid column, so each combination costs a small solve), refined by Ceres.
  Solution solve(int terms) const {
    Solution start;
    std::vector<int> grid_index(terms);
    for (int k = 0; k < terms; ++k) grid_index[k] = k;
    while (true) {
      std::vector<Eigen::Index> chosen{0};
      for (int index : grid_index) chosen.push_back(1 + index);
      const auto size = static_cast<Eigen::Index>(chosen.size());
      Eigen::MatrixXd gram(size, size);
      Eigen::VectorXd projection(size);
      for (Eigen::Index i = 0; i < size; ++i) {
        projection[i] = grid_projection_[chosen[i]];
        for (Eigen::Index j = 0; j < size; ++j) gram(i, j) = grid_gram_(chosen[i], chosen[j]);
      }
      const Eigen::VectorXd coefficients = gram.ldlt().solve(projection);
      const double rss = target_.squaredNorm() - coefficients.dot(projection);
      if (coefficients.allFinite() && rss < start.residual_sum_of_squares) {
        start.residual_sum_of_squares = rss;
        start.parameters.assign(1, coefficients[0]);
        for (int k = 0; k < terms; ++k) {
          start.parameters.push_back(coefficients[1 + k]);
          start.parameters.push_back(grid_s_[grid_index[k]]);
        }
      }
      if (!next_combination(&grid_index)) break;
    }
    if (terms == 0) {
      start.usable = true;
      return start;
    }
    Solution solution = start;
    ceres::Problem problem;
    problem.AddResidualBlock(new WarmUpCost(blocks_, root_weights_, terms), nullptr, solution.parameters.data());
    for (int k = 0; k < terms; ++k) {
      problem.SetParameterLowerBound(solution.parameters.data(), 2 + 2 * k, lowest_s_);
      problem.SetParameterUpperBound(solution.parameters.data(), 2 + 2 * k, highest_s_);
    }
    const ceres::Solver::Options solver = small_fit_solver_options({200, 1e-12, 1e-14, 1e-12});
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    solution.residual_sum_of_squares = 2.0 * summary.final_cost;
    // A time constant at its bound is not a settling transient the record resolves.
    solution.usable = summary.IsSolutionUsable() && std::isfinite(summary.final_cost);
    for (int k = 0; k < terms; ++k) {
      const double time_constant_s = solution.parameters[2 + 2 * k];
      solution.usable &= time_constant_s > 1.01 * lowest_s_ && time_constant_s < 0.99 * highest_s_;
    }
    return solution;
  }

  // Weighted residuals of a solution, in block order.
  std::vector<double> residuals(const Solution& solution, int terms) const {
    std::vector<double> values(blocks_.size());
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      values[i] = root_weights_[i] * (blocks_[i].mean - block_model(blocks_[i], solution.parameters.data(), terms));
    }
    return values;
  }

  // (J^T W J)^-1 at a solution.
  Eigen::MatrixXd inverse_normal_matrix(const Solution& solution, int terms) const {
    const int size = 1 + 2 * terms;
    Eigen::MatrixXd jacobian(static_cast<Eigen::Index>(blocks_.size()), size);
    std::vector<double> gradient(size);
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      block_gradient(blocks_[i], solution.parameters.data(), terms, gradient.data());
      for (int p = 0; p < size; ++p) jacobian(static_cast<Eigen::Index>(i), p) = root_weights_[i] * gradient[p];
    }
    const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
    return normal.ldlt().solve(Eigen::MatrixXd::Identity(size, size));
  }

  const std::vector<double>& root_weights() const { return root_weights_; }

 private:
  Eigen::MatrixXd columns(const std::vector<double>& time_constants) const {
    Eigen::MatrixXd matrix(static_cast<Eigen::Index>(blocks_.size()),
                           1 + static_cast<Eigen::Index>(time_constants.size()));
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      matrix(row, 0) = root_weights_[i];
      for (std::size_t k = 0; k < time_constants.size(); ++k) {
        matrix(row, 1 + static_cast<Eigen::Index>(k)) =
            root_weights_[i] * exponential_average(blocks_[i].start_s, blocks_[i].end_s, time_constants[k]).value;
      }
    }
    return matrix;
  }

  // Next strictly increasing index tuple over the grid (lexicographic); false after the last.
  bool next_combination(std::vector<int>* indices) const {
    const int count = static_cast<int>(indices->size());
    const int n = static_cast<int>(grid_s_.size());
    for (int k = count - 1; k >= 0; --k) {
      if ((*indices)[k] < n - count + k) {
        ++(*indices)[k];
        for (int j = k + 1; j < count; ++j) (*indices)[j] = (*indices)[j - 1] + 1;
        return true;
      }
    }
    return false;
  }

  const std::vector<WarmUpBlock>& blocks_;
  WarmUpFitOptions options_;
  std::vector<double> root_weights_;
  Eigen::VectorXd target_;
  double lowest_s_ = 0.0;
  double highest_s_ = 0.0;
  std::vector<double> grid_s_;
  Eigen::MatrixXd grid_gram_;        // of the constant and every grid column
  Eigen::VectorXd grid_projection_;  // those columns times the target
};

// How much more a mean over m blocks of the residuals varies than it would for independent
// blocks, r(m) = m AVAR(m) / AVAR(1) (overlapping Allan variance of the residual series): 1 for
// white noise, 1 + c1 m for flicker (flat AVAR), 1 + c2 m^2 for random walk (AVAR ~ tau). The
// estimate at m near the fit's time constants is poor (few independent terms, and the fit has
// absorbed part of the wander there), so r is measured at octaves up to a 32nd of the record,
// fitted with 1 + c1 m + c2 m^2 (c1, c2 >= 0; each point weighted by its term count) and taken at
// m = at_blocks. At least 1: never credit the fit with less than independent blocks.
double correlation_inflation(const std::vector<double>& residuals, std::size_t at_blocks) {
  const std::size_t n = residuals.size();
  std::vector<double> phase(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) phase[i + 1] = phase[i] + residuals[i];
  const auto avar = [&](std::size_t m) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k + 2 * m <= n; ++k, ++count) {
      const double d = phase[k + 2 * m] - 2.0 * phase[k + m] + phase[k];
      sum += d * d;
    }
    return count == 0 ? 0.0 : sum / (2.0 * static_cast<double>(m * m) * static_cast<double>(count));
  };
  const double single = avar(1);
  if (!(single > 0.0)) return 1.0;
  // Rows m, m^2 scaled by sqrt(n / m) / r (relative error, about n / m independent terms).
  std::vector<double> factors, excess, weights;
  for (std::size_t m = 2; m <= n / 32; m *= 2) {
    const double r = static_cast<double>(m) * avar(m) / single;
    factors.push_back(static_cast<double>(m));
    excess.push_back(r - 1.0);
    weights.push_back(std::sqrt(static_cast<double>(n) / static_cast<double>(m)) / std::max(r, 1.0));
  }
  if (factors.empty()) return 1.0;
  const auto fit_terms = [&](bool linear, bool quadratic) {
    const int size = (linear ? 1 : 0) + (quadratic ? 1 : 0);
    Eigen::MatrixXd rows(static_cast<Eigen::Index>(factors.size()), size);
    Eigen::VectorXd target(static_cast<Eigen::Index>(factors.size()));
    for (std::size_t i = 0; i < factors.size(); ++i) {
      const auto row = static_cast<Eigen::Index>(i);
      int column = 0;
      if (linear) rows(row, column++) = weights[i] * factors[i];
      if (quadratic) rows(row, column++) = weights[i] * factors[i] * factors[i];
      target[row] = weights[i] * excess[i];
    }
    const Eigen::VectorXd c = rows.colPivHouseholderQr().solve(target);
    Eigen::Vector2d both = Eigen::Vector2d::Zero();
    int column = 0;
    if (linear) both[0] = c[column++];
    if (quadratic) both[1] = c[column++];
    return both;
  };
  Eigen::Vector2d c = fit_terms(true, true);
  if (c[0] < 0.0 || c[1] < 0.0) {
    const Eigen::Vector2d only_linear = fit_terms(true, false);
    const Eigen::Vector2d only_quadratic = fit_terms(false, true);
    c = Eigen::Vector2d::Zero();
    if (only_linear[0] > 0.0) c = only_linear;
    if (only_quadratic[1] > 0.0) {
      const auto m = static_cast<double>(at_blocks);
      if (only_quadratic[1] * m * m > c[0] * m) c = only_quadratic;
    }
  }
  const auto m = static_cast<double>(at_blocks);
  return std::max(1.0, 1.0 + c[0] * m + c[1] * m * m);
}

// P(F(2, dof) > statistic), exact for two numerator degrees of freedom.
double f_test_upper_tail(double statistic, double dof) {
  if (!(statistic > 0.0)) return 1.0;
  return std::pow(1.0 + 2.0 * statistic / dof, -dof / 2.0);
}

// The averaging the inflation looks at: the longest time constant of the fit (its parameters are
// informed over that long), at least an eighth of the record.
std::size_t correlation_lags(const std::vector<double>& parameters, int terms, std::size_t block_count,
                             double block_s) {
  double longest_s = 0.0;
  for (int k = 0; k < terms; ++k) longest_s = std::max(longest_s, parameters[2 + 2 * k]);
  const std::size_t eighth = std::max<std::size_t>(1, block_count / 8);
  if (terms == 0) return eighth;
  return std::min(eighth, static_cast<std::size_t>(std::max(1.0, std::round(longest_s / block_s))));
}

LinearTrend fit_trend(const std::vector<WarmUpBlock>& blocks, const std::vector<double>& root_weights,
                      const WarmUpFit& fit) {
  const auto n = static_cast<Eigen::Index>(blocks.size());
  Eigen::MatrixXd columns(n, 2);
  Eigen::VectorXd target(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const WarmUpBlock& block = blocks[static_cast<std::size_t>(i)];
    const double w = root_weights[static_cast<std::size_t>(i)];
    double transient = 0.0;
    for (const WarmUpTerm& term : fit.terms) {
      transient += term.amplitude * exponential_average(block.start_s, block.end_s, term.time_constant_s).value;
    }
    columns(i, 0) = w;
    columns(i, 1) = w * 0.5 * (block.start_s + block.end_s);
    target[i] = w * (block.mean - transient);
  }
  Eigen::VectorXd coefficients;
  const double rss = linear_fit(columns, target, &coefficients);
  std::vector<double> residuals(static_cast<std::size_t>(n));
  const Eigen::VectorXd r = target - columns * coefficients;
  for (Eigen::Index i = 0; i < n; ++i) residuals[static_cast<std::size_t>(i)] = r[i];
  const double inflation = correlation_inflation(residuals, correlation_lags({}, 0, blocks.size(), 1.0));
  const Eigen::Matrix2d normal = columns.transpose() * columns;
  const Eigen::Matrix2d covariance = normal.inverse() * (rss / static_cast<double>(n - 2)) * inflation;
  LinearTrend trend;
  trend.value_at_start = coefficients[0];
  trend.slope_per_s = coefficients[1];
  trend.slope_sigma_per_s = std::sqrt(covariance(1, 1));
  return trend;
}

}  // namespace

WarmUpBlockMeans::WarmUpBlockMeans(std::size_t channel_count, double block_s)
    : channel_count_(channel_count), block_s_(block_s), blocks_(channel_count) {
  if (channel_count == 0) throw std::invalid_argument("warm-up block means: no channel");
  if (!(block_s > 0.0) || !std::isfinite(block_s)) {
    throw std::invalid_argument("warm-up block means: the block length must be a positive number of seconds");
  }
  current_.sums.assign(channel_count, 0.0);
  current_.counts.assign(channel_count, 0);
}

void WarmUpBlockMeans::push(std::int64_t stamp_ns, const double* values) {
  if (!started_) {
    started_ = true;
    first_stamp_ns_ = stamp_ns;
  }
  const double time_s = static_cast<double>(stamp_ns - first_stamp_ns_) * 1e-9;
  const auto index = static_cast<long long>(std::floor(time_s / block_s_));
  if (index != current_.index) {
    close_block();
    current_.index = index;
    current_.first_s = time_s;
  }
  current_.last_s = time_s;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    if (!std::isfinite(values[c])) continue;
    current_.sums[c] += values[c];
    ++current_.counts[c];
  }
}

void WarmUpBlockMeans::close_block() {
  if (current_.index < 0) return;
  for (std::size_t c = 0; c < channel_count_; ++c) {
    if (current_.counts[c] > 0) {
      blocks_[c].push_back({current_.first_s, current_.last_s,
                            current_.sums[c] / static_cast<double>(current_.counts[c]), current_.counts[c]});
    }
    current_.sums[c] = 0.0;
    current_.counts[c] = 0;
  }
}

std::vector<WarmUpBlock> WarmUpBlockMeans::blocks(std::size_t channel) const {
  std::vector<WarmUpBlock> result = blocks_.at(channel);
  if (current_.index >= 0 && current_.counts[channel] > 0) {
    result.push_back({current_.first_s, current_.last_s,
                      current_.sums[channel] / static_cast<double>(current_.counts[channel]),
                      current_.counts[channel]});
  }
  return result;
}

double WarmUpFit::transient(double time_s) const {
  double value = 0.0;
  for (const WarmUpTerm& term : terms) value += term.amplitude * std::exp(-time_s / term.time_constant_s);
  return value;
}

double WarmUpFit::transient_sigma(double time_s) const {
  if (terms.empty()) return 0.0;
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(covariance.rows());
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const double decay = std::exp(-time_s / terms[k].time_constant_s);
    gradient[static_cast<Eigen::Index>(1 + 2 * k)] = decay;
    gradient[static_cast<Eigen::Index>(2 + 2 * k)] =
        terms[k].amplitude * decay * time_s / (terms[k].time_constant_s * terms[k].time_constant_s);
  }
  return std::sqrt(std::max(0.0, gradient.dot(covariance * gradient)));
}

WarmUpFit fit_warm_up(const std::vector<WarmUpBlock>& blocks, double block_s, const WarmUpFitOptions& options) {
  const std::size_t needed = 1 + 2 * static_cast<std::size_t>(std::max(0, options.max_terms)) + kSpareBlocks;
  if (blocks.size() < needed) {
    throw std::invalid_argument("a warm-up fit with up to " + std::to_string(options.max_terms) +
                                " exponentials needs at least " + std::to_string(needed) + " blocks; there are " +
                                std::to_string(blocks.size()) + " (a longer record or shorter blocks)");
  }
  const WarmUpFitter fitter(blocks, block_s, options);
  const auto n = static_cast<double>(blocks.size());
  Solution chosen = fitter.solve(0);
  int chosen_terms = 0;
  WarmUpFit fit;
  for (int terms = 1; terms <= options.max_terms; ++terms) {
    const Solution candidate = fitter.solve(terms);
    if (!candidate.usable) {
      fit.added_term_p.push_back(1.0);
      break;
    }
    const double dof = n - (1 + 2 * terms);
    const double inflation = correlation_inflation(
        fitter.residuals(candidate, terms), correlation_lags(candidate.parameters, terms, blocks.size(), block_s));
    // The drop in RSS for two more parameters against the residual variance, the latter scaled
    // by the residuals' correlation as the sigmas are.
    const double statistic = (chosen.residual_sum_of_squares - candidate.residual_sum_of_squares) / 2.0 /
                             (candidate.residual_sum_of_squares / dof * inflation);
    const double p = f_test_upper_tail(statistic, dof);
    fit.added_term_p.push_back(p);
    if (!(p < options.significance)) break;
    chosen = candidate;
    chosen_terms = terms;
  }

  const int size = 1 + 2 * chosen_terms;
  const std::vector<double> residuals = fitter.residuals(chosen, chosen_terms);
  fit.correlation_inflation =
      correlation_inflation(residuals, correlation_lags(chosen.parameters, chosen_terms, blocks.size(), block_s));
  const double residual_variance = chosen.residual_sum_of_squares / (n - size);
  fit.covariance = fitter.inverse_normal_matrix(chosen, chosen_terms) * residual_variance * fit.correlation_inflation;
  fit.block_count = blocks.size();
  fit.block_s = block_s;
  fit.record_s = blocks.back().end_s;
  double unweighted = 0.0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const double r = residuals[i] / fitter.root_weights()[i];
    unweighted += r * r;
  }
  fit.residual_rms = std::sqrt(unweighted / n);
  fit.constant = chosen.parameters[0];
  fit.constant_sigma = std::sqrt(fit.covariance(0, 0));
  for (int k = 0; k < chosen_terms; ++k) {
    WarmUpTerm term;
    term.amplitude = chosen.parameters[1 + 2 * k];
    term.time_constant_s = chosen.parameters[2 + 2 * k];
    term.amplitude_sigma = std::sqrt(fit.covariance(1 + 2 * k, 1 + 2 * k));
    term.time_constant_sigma_s = std::sqrt(fit.covariance(2 + 2 * k, 2 + 2 * k));
    fit.terms.push_back(term);
  }
  // By increasing time constant, the covariance's rows and columns with them.
  std::vector<int> order(chosen_terms);
  for (int k = 0; k < chosen_terms; ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return fit.terms[a].time_constant_s < fit.terms[b].time_constant_s; });
  Eigen::VectorXi permutation(size);
  permutation[0] = 0;
  std::vector<WarmUpTerm> sorted;
  for (int k = 0; k < chosen_terms; ++k) {
    sorted.push_back(fit.terms[order[k]]);
    permutation[1 + 2 * k] = 1 + 2 * order[k];
    permutation[2 + 2 * k] = 2 + 2 * order[k];
  }
  Eigen::MatrixXd reordered(size, size);
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < size; ++j) reordered(i, j) = fit.covariance(permutation[i], permutation[j]);
  }
  fit.covariance = reordered;
  fit.terms = sorted;
  fit.trend = fit_trend(blocks, fitter.root_weights(), fit);
  return fit;
}

}  // namespace thermal
}  // namespace imu_lab
