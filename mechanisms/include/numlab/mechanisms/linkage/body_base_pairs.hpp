#pragma once
// Which two joints of each body carry its other joints (docs/linkage-files.md, "Blocks: the order
// of solving"). A body of n joints gives 2n - 3 rows: the distance of its base pair b0, b1, and two
// rows per further joint c placing it from b0 and b1. Any pair describes the same rigid body, but
// not the same blocks: a further joint placed from a pair that is solved after it ties the three
// together, and a pantograph's dyads become one Newton block. So the pair is not the file's first
// two joints but the body's first two joints to be known, found by following the mechanism from the
// ground, round by round, as a draftsman would construct it:
//
//   1. the ground joints are known (round 0);
//   2. a joint becomes known in the next round when
//        - a body holds it with two joints already known (a body point), or
//        - two rows fix it from known joints: the rows of the other items (links, sliders, the
//          driver) that read it and known joints only, and one distance per body that holds it with
//          exactly one known joint (a dyad, or the crank, or a driven slider);
//   3. when no joint becomes known so, the smallest blocks of the model with the pairs chosen so
//      far (linkage_blocks.hpp) that need only known joints are solved by Newton: their joints
//      become known in the next round, and step 2 goes on from there. A body with a joint in them
//      first tries each of its pairs (one body at a time, in the order of the joints' names) and
//      keeps one that makes them smaller: a pair from outside the block would tie a later joint in;
//   4. each body's base pair is its two joints known first; joints known in the same round (or
//      never: a model that is not regular) are taken in the order of their names. The two keep
//      the order in which the body lists them: which one is b0 changes the rows, not the blocks.
//
// Nothing here depends on the order of the file's joints, links, bodies, or of a body's joints, so
// neither do the blocks. The crank's own body keeps the crank's pivot and joint as its pair
// (LinkageModel), which step 2 also finds.

#include <array>
#include <vector>

namespace numlab::mechanisms {

class LinkageModel;

// One base pair per body of model.description(), as indices into the body's joints. The model's
// non-body constraints are read; its own base pairs are not.
std::vector<std::array<int, 2>> body_base_pairs(const LinkageModel& model);

// The round in which each joint becomes known (steps 1 to 3), -1 for a joint never known.
std::vector<int> known_rounds(const LinkageModel& model);

}  // namespace numlab::mechanisms
