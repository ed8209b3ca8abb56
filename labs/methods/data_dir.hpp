#pragma once
// Where numlab's data is: beside an installed numlab, or in the source tree it was built from.

#include <string>

namespace numlab::cli {

// The folder of the NIST .dat files, looked up in this order:
//   1. $NUMLAB_DATA_DIR/nist, when that variable is set;
//   2. PREFIX/share/numlab/nist, where PREFIX is the folder above the running executable's bin/
//      (an installed numlab: the data is installed with it);
//   3. the source tree's fitting/data/nist (a numlab run from its build tree).
// Throws std::invalid_argument, listing the places looked in, when none holds Wampler4.dat.
std::string nist_data_dir();

// The folder of the example solutions `lab exercises` runs, looked up the same way:
// $NUMLAB_DATA_DIR/examples, PREFIX/share/numlab/examples, the source tree's labs/exercises/examples.
// Throws std::invalid_argument, listing the places looked in, when none holds gepp_solution.py.
std::string examples_dir();

// The folder of the linkage models shipped as description files (`numlab models`, `numlab mechanism
// four-bar`), looked up the same way: $NUMLAB_DATA_DIR/models, PREFIX/share/numlab/models, the
// source tree's mechanisms/models. Throws std::invalid_argument, listing the places looked in, when
// none holds four-bar.toml.
std::string models_dir();

}  // namespace numlab::cli
