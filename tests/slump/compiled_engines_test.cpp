// The engine list: every shipped scene runs on a compiled engine, with and without the ledger, and
// a choice the list lacks is refused naming it and the list (exit 2 at the command line).
#include <catch2/catch.hpp>
#include <filesystem>

#include "core/input_error.hpp"
#include "slump/compiled_engines.hpp"

using namespace demscale;
using namespace demscale::slump;

TEST_CASE("Every shipped scene's laws are a compiled engine, with and without the ledger", "[slump][engines]") {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(DEMSCALE_SOURCE_DIR "/data/scenes")) {
        const SlumpScene s = load_slump_scene(entry.path().string());
        for (const bool ledger : {false, true}) {
            const EngineLine line = listed_engine(s, ledger);
            INFO(entry.path().filename().string() << ": " << engine_name(line, &s));
            CHECK(line.ledger == ledger);
            CHECK((line.rolling != RollingEngine::none) == s.rolling_resistance);
            CHECK((line.cohesion == CohesionChoice::liquid_bridge) == (s.wet && s.sizes.monodisperse()));
            CHECK((line.cohesion == CohesionChoice::liquid_bridge_pairs) == (s.wet && !s.sizes.monodisperse()));
            CHECK(line.normal->active(s));
        }
        ++scenes;
    }
    CHECK(scenes >= 5);
}

TEST_CASE("A scene whose laws are on no line of the list is refused, naming its laws and the list", "[slump][engines]") {
    SlumpScene s = load_slump_scene(DEMSCALE_SOURCE_DIR "/data/scenes/kantro_dry.toml");
    s.rolling_model = RollingModel::epsd2;
    const EngineLine wet_only[] = {{&dem::hertz_part, CohesionChoice::liquid_bridge, RollingEngine::epsd, false}};
    try {
        listed_engine(s, false, false, wet_only);
        FAIL("a dry scene ran on a list of one wet engine");
    } catch (const InputError& e) {
        CHECK(e.value() == "the contact laws Hertz normal contact, no cohesion, epsd2 rolling");
        CHECK(e.accepted() == "one of the compiled engines (lib/slump/compiled_engines.hpp): Hertz normal contact, liquid bridge, epsd rolling");
        CHECK(e.field().find("kantro_dry.toml") != std::string::npos);
    }
    // The ledger is part of the choice: the same scene with the ledger is not the line without it.
    const EngineLine dry_plain[] = {{&dem::hertz_part, CohesionChoice::none, RollingEngine::run_time, false}};
    CHECK_NOTHROW(listed_engine(s, false, false, dry_plain));
    CHECK_THROWS_AS(listed_engine(s, true, false, dry_plain), InputError);
    // The shipped list compiles no ledger for the run-time rolling laws.
    CHECK_THROWS_AS(listed_engine(s, true), InputError);
}
