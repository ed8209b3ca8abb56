#pragma once
// The frame every lab shares: numbered, explained steps (pausing between them with --step),
// tables, and the closing comparison of hand-written methods with GSL.

#include <Eigen/Core>
#include <ostream>
#include <string>
#include <vector>

#include "table.hpp"

namespace numlab::cli {

class LabSession {
 public:
  LabSession(std::ostream& out, bool step, std::string out_dir)
      : out_(out), step_(step), out_dir_(std::move(out_dir)) {}

  // Starts the next step: pauses first (with --step, after step 1), then prints its title and explanation.
  void begin_step(const std::string& title, const std::string& explanation);
  // A paragraph, wrapped to 96 columns and indented.
  void say(const std::string& paragraph);
  void show(const Table& table);

  std::ostream& out() { return out_; }
  const std::string& out_dir() const { return out_dir_; }
  int steps_taken() const { return step_number_; }

 private:
  std::ostream& out_;
  bool step_;
  std::string out_dir_;
  int step_number_ = 0;
};

struct Lab {
  std::string name;
  std::string summary;
  int (*run)(LabSession&);  // returns an exit code
};

const std::vector<Lab>& all_labs();

// The closing table of a linear lab: each method's answer, relative residual, forward error and
// median time on A x = b.
Table linear_comparison_table(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& exact,
                              const std::vector<std::string>& methods);

int run_gauss_lab(LabSession& session);
int run_seidel_lab(LabSession& session);
int run_inverse2x2_lab(LabSession& session);

}  // namespace numlab::cli
