// Running another program: its exit code and both its streams come back; a missing program is 127.
#include <catch2/catch.hpp>

#include "core/subprocess.hpp"

using namespace demscale;

TEST_CASE("Subprocess: exit code and both streams, arguments passed without a shell", "[core][subprocess]") {
    const auto out = run_command({"sh", "-c", "echo out; echo err >&2; exit 3"});
    CHECK(out.exit_code == 3);
    CHECK(out.output.find("out\n") != std::string::npos);
    CHECK(out.output.find("err\n") != std::string::npos);
    // A quote and a space stay inside one argument.
    const auto echo = run_command({"printf", "%s|", "it's one", "$HOME"});
    CHECK(echo.exit_code == 0);
    CHECK(echo.output == "it's one|$HOME|");
    CHECK(run_command({"demscale-no-such-program"}).exit_code == 127);
}
