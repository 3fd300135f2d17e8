// Whether a study looks again at seeds an earlier study already ran: every run of some seeds came
// from the cache and no run of the others did. A verdict or k̂ taken after adding seeds because the
// first look was marginal is optional stopping: its 95 % intervals are no longer exact
// (docs/verdicts.md, "Levels of the test"). The study cannot know why it was run; it says what the
// cache shows.
#pragma once

#include <string>
#include <vector>

#include "slump/run_batch.hpp"

namespace demscale::slump {

struct SecondLook {
    std::vector<unsigned> earlier;  // seeds whose every run came from the cache
    std::vector<unsigned> added;    // seeds none of whose runs did
    bool any() const { return !earlier.empty() && !added.empty(); }
    // One sentence for a table's notes and the command's output; empty when it is not a second look.
    std::string describe() const;
};

// From a finished batch; a seed with some runs cached and some not (an interrupted study resumed,
// levels added) makes it no second look.
SecondLook second_look(const std::vector<StudyRun*>& runs);

}  // namespace demscale::slump
