#pragma once
// The linkage exercise under a variant (issue 29 §4; docs/exercises.md, "A variant per student"):
// the description file's numbers that shape the mechanism, each times 1 + u with u uniform in
// [-3%, 3%) from the ID's stream (variant_lengths.hpp): every link's length, every body's local
// coordinates (a zero stays zero: a joint on a body's axis stays on it), and every ground joint's
// offset from the first ground joint (which stays where the file puts it). Slider lines, the
// driver's reference value and the moving joints' rough positions are the file's.

#include <functional>
#include <memory>

#include "exercises/variant.hpp"
#include "numlab/mechanisms/linkage/linkage_model.hpp"

namespace numlab::exercises {

// The file's model without a variant; with one, the first draw whose model `valid` accepts (the
// exercise's test: numlab's sweep covers the file's, pose for pose, on the same branch).
std::shared_ptr<const mechanisms::LinkageModel> linkage_variant(
    std::shared_ptr<const mechanisms::LinkageModel> file, const Variant& variant,
    const std::function<bool(std::shared_ptr<const mechanisms::LinkageModel>)>& valid);

}  // namespace numlab::exercises
