#include "solve/ipopt_local.h"

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <numeric>
#include <sstream>

#include "tolerances.h"

namespace pd {

std::vector<int> all_indices(Eigen::Index n) {
  std::vector<int> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  return idx;
}

namespace {

using Ipopt::Index;
using Ipopt::Number;

// Variables x = (v1, v2, v3, c, α). Constraint rows: first the Q rows
// (q_j·v − c + α >= 0), then the P rows (p_i·v − c <= 0), last v·v = 1.
class DepthTnlp : public Ipopt::TNLP {
 public:
  DepthTnlp(const Points& p, const Points& q, const std::vector<int>& pi,
            const std::vector<int>& qj, const LocalStart& start, bool alpha_free)
      : p_(p), q_(q), pi_(pi), qj_(qj), start_(start), alpha_free_(alpha_free) {}

  LocalOutcome outcome;

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = 5;
    m = static_cast<Index>(qj_.size() + pi_.size() + 1);
    nnz_jac = static_cast<Index>(5 * qj_.size() + 4 * pi_.size() + 3);
    nnz_h = 3;
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* xl, Number* xu, Index m, Number* gl, Number* gu) override {
    for (Index k = 0; k < n; ++k) {
      xl[k] = -2e19;
      xu[k] = 2e19;
    }
    if (!alpha_free_) xl[4] = 0.0;  // α >= 0 (free: the signed distance of separated pairs)
    const Index nq = static_cast<Index>(qj_.size());
    for (Index r = 0; r < m - 1; ++r) {
      gl[r] = r < nq ? 0.0 : -2e19;
      gu[r] = r < nq ? 2e19 : 0.0;
    }
    gl[m - 1] = gu[m - 1] = 1.0;
    return true;
  }

  bool get_starting_point(Index, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (init_z || init_lambda) return false;
    if (init_x) {
      x[0] = start_.v.x();
      x[1] = start_.v.y();
      x[2] = start_.v.z();
      x[3] = start_.c;
      x[4] = alpha_free_ ? start_.alpha : std::max(start_.alpha, 0.0);
    }
    return true;
  }

  bool eval_f(Index, const Number* x, bool, Number& f) override {
    f = x[4];
    return true;
  }
  bool eval_grad_f(Index, const Number*, bool, Number* g) override {
    g[0] = g[1] = g[2] = g[3] = 0.0;
    g[4] = 1.0;
    return true;
  }

  bool eval_g(Index, const Number* x, bool, Index m, Number* g) override {
    const Vec3 v(x[0], x[1], x[2]);
    Index r = 0;
    for (int j : qj_) g[r++] = q_.col(j).dot(v) - x[3] + x[4];
    for (int i : pi_) g[r++] = p_.col(i).dot(v) - x[3];
    g[m - 1] = v.squaredNorm();
    return true;
  }

  bool eval_jac_g(Index, const Number* x, bool, Index m, Index, Index* row, Index* col,
                  Number* val) override {
    Index k = 0;
    if (val == nullptr) {
      Index r = 0;
      for (size_t s = 0; s < qj_.size(); ++s, ++r)
        for (Index c = 0; c < 5; ++c) row[k] = r, col[k++] = c;
      for (size_t s = 0; s < pi_.size(); ++s, ++r)
        for (Index c = 0; c < 4; ++c) row[k] = r, col[k++] = c;
      for (Index c = 0; c < 3; ++c) row[k] = m - 1, col[k++] = c;
      return true;
    }
    for (int j : qj_) {
      val[k++] = q_(0, j), val[k++] = q_(1, j), val[k++] = q_(2, j);
      val[k++] = -1.0, val[k++] = 1.0;
    }
    for (int i : pi_) {
      val[k++] = p_(0, i), val[k++] = p_(1, i), val[k++] = p_(2, i);
      val[k++] = -1.0;
    }
    for (Index c = 0; c < 3; ++c) val[k++] = 2.0 * x[c];
    return true;
  }

  bool eval_h(Index, const Number*, bool, Number, Index m, const Number* lambda, bool, Index,
              Index* row, Index* col, Number* val) override {
    if (val == nullptr) {
      for (Index c = 0; c < 3; ++c) row[c] = col[c] = c;
      return true;
    }
    for (Index c = 0; c < 3; ++c) val[c] = 2.0 * lambda[m - 1];
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Index, const Number* x, const Number*, const Number*,
                         Index, const Number*, const Number*, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    Vec3 v(x[0], x[1], x[2]);
    const double nv = v.norm();
    outcome.v = nv > 0 && std::isfinite(nv) ? Vec3(v / nv) : start_.v;
    outcome.c = x[3];
    outcome.alpha = x[4];
  }

 private:
  const Points& p_;
  const Points& q_;
  const std::vector<int>& pi_;
  const std::vector<int>& qj_;
  LocalStart start_;
  bool alpha_free_;
};

const char* status_name(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded:
      return "solve_succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "solved_to_acceptable_level";
    case Ipopt::Infeasible_Problem_Detected:
      return "infeasible_problem_detected";
    case Ipopt::Search_Direction_Becomes_Too_Small:
      return "search_direction_too_small";
    case Ipopt::Diverging_Iterates:
      return "diverging_iterates";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "maximum_iterations_exceeded";
    case Ipopt::Restoration_Failed:
      return "restoration_failed";
    case Ipopt::Error_In_Step_Computation:
      return "error_in_step_computation";
    case Ipopt::Maximum_CpuTime_Exceeded:
      return "maximum_cputime_exceeded";
    case Ipopt::Invalid_Number_Detected:
      return "invalid_number_detected";
    default:
      return "ipopt_error";
  }
}

}  // namespace

struct IpoptLocalSolver::Impl {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app;
};

IpoptLocalSolver::IpoptLocalSolver() : impl_(new Impl) {
  impl_->app = IpoptApplicationFactory();
  auto& o = *impl_->app->Options();
  o.SetIntegerValue("print_level", 0);
  o.SetStringValue("sb", "yes");
  o.SetNumericValue("tol", tol::kIpoptTol);
  o.SetIntegerValue("max_iter", tol::kIpoptMaxIter);
  o.SetStringValue("hessian_approximation", "exact");
  // An empty file name: an ipopt.opt in the working directory must not change results.
  impl_->app->Initialize("");
}

IpoptLocalSolver::~IpoptLocalSolver() = default;

LocalStart IpoptLocalSolver::paper_start(const Points& p, const Points& q, const Vec3& v0) {
  LocalStart s;
  s.v = v0;
  s.c = (v0.transpose() * p).maxCoeff();
  s.alpha = s.c - (v0.transpose() * q).minCoeff();
  return s;
}

LocalOutcome IpoptLocalSolver::solve(const Points& p, const Points& q, const std::vector<int>& pi,
                                     const std::vector<int>& qj, const LocalStart& start, bool warm,
                                     bool alpha_free) {
  auto& o = *impl_->app->Options();
  // A start next to the optimum needs no large barrier: a small mu_init and a
  // small push off the bounds keep Ipopt from walking away first.
  o.SetNumericValue("mu_init", warm ? 1e-6 : 0.1);
  o.SetNumericValue("bound_push", warm ? 1e-8 : 1e-2);
  o.SetNumericValue("bound_frac", warm ? 1e-8 : 1e-2);
  Ipopt::SmartPtr<DepthTnlp> nlp = new DepthTnlp(p, q, pi, qj, start, alpha_free);
  const Ipopt::ApplicationReturnStatus st = impl_->app->OptimizeTNLP(nlp);
  LocalOutcome out = nlp->outcome;
  out.status = status_name(st);
  auto stats = impl_->app->Statistics();
  out.iterations = IsValid(stats) ? stats->IterationCount() : 0;
  out.converged = st == Ipopt::Solve_Succeeded || st == Ipopt::Solved_To_Acceptable_Level;
  if (!std::isfinite(out.alpha) || !out.v.allFinite()) out.converged = false;
  return out;
}

}  // namespace pd
