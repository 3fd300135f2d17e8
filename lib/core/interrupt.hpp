// Stopping long runs cleanly: SIGINT and SIGTERM only raise a flag; DEM loops poll it at step
// boundaries, write a checkpoint and throw Interrupted. A second signal ends the process at once.
#pragma once

#include <stdexcept>
#include <string>

namespace demscale {

void install_interrupt_handlers();
bool interrupt_requested();
void request_interrupt();  // what the handler does; also for tests
void clear_interrupt();

class Interrupted : public std::runtime_error {
public:
    Interrupted(const std::string& what, std::string checkpoint)
        : std::runtime_error(what), checkpoint_(std::move(checkpoint)) {}
    const std::string& checkpoint() const { return checkpoint_; }  // empty: none written

private:
    std::string checkpoint_;
};

}  // namespace demscale
