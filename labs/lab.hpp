#pragma once
// The frame every lab shares: numbered, explained steps (pausing between them with --step),
// tables (printed, and saved as CSV files), and the closing comparison of hand-written methods with GSL.

#include <Eigen/Core>
#include <ostream>
#include <string>
#include <vector>

#include "table.hpp"

namespace numlab::cli {

class LabSession {
 public:
  // Tables are also saved as CSV files in `folder` (created on first use).
  LabSession(std::ostream& out, bool step, std::string folder) : out_(out), step_(step), folder_(std::move(folder)) {}

  // Starts the next step: pauses first (with --step, after step 1), then prints its title and explanation.
  void begin_step(const std::string& title, const std::string& explanation);
  // A paragraph, wrapped to 96 columns and indented.
  void say(const std::string& paragraph);
  // Prints the table and saves it as FOLDER/stepK-NAME.csv.
  void show(const Table& table, const std::string& name);

  std::ostream& out() { return out_; }
  const std::string& folder() const { return folder_; }
  int steps_taken() const { return step_number_; }

 private:
  std::ostream& out_;
  bool step_;
  std::string folder_;
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
int run_newton_lab(LabSession& session);
int run_jansen_lab(LabSession& session);
int run_jansen_sequential_lab(LabSession& session);
int run_beest_lab(LabSession& session);
int run_mustang_lab(LabSession& session);

}  // namespace numlab::cli
