// Piles from other engines: every value is checked against the text written by hand here.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/input_error.hpp"
#include "io/csv_reader.hpp"
#include "io/particle_state.hpp"
#include "io/pile_file.hpp"

using namespace demscale;
using Catch::Matchers::Contains;

namespace {
double sphere_mass(double r, double rho) { return rho * 4.0 / 3.0 * std::numbers::pi * r * r * r; }
}  // namespace

TEST_CASE("A LAMMPS dump is read in any column order, its last snapshot", "[io][pile]") {
    const std::string dump =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\nITEM: ATOMS id type x y z radius\n"
        "1 1 0.5 0.5 0.5 0.002\n"
        "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\nITEM: ATOMS id radius z type y x\n"
        "7 0.001 0.003 1 -0.02 0.01\n"
        "8 1.5e-3 4e-3 1 0 -0.01\n";
    const auto p = io::parse_pile(dump, "f.dump", 2500);
    CHECK(p.kind == "dump");
    CHECK(p.snapshots == 2);
    REQUIRE(p.particles.size() == 2);
    CHECK(p.particles.position[0].x() == 0.01);
    CHECK(p.particles.position[0].y() == -0.02);
    CHECK(p.particles.position[0].z() == 0.003);
    CHECK(p.particles.radius[0] == 0.001);
    CHECK(p.particles.radius[1] == 1.5e-3);
    CHECK(p.particles.mass[1] == Approx(sphere_mass(1.5e-3, 2500)).epsilon(1e-14));
    // A diameter column is halved; a density column overrides the scene's.
    const auto d = io::parse_pile("ITEM: ATOMS id type xu yu zu diameter density\n1 1 0 0 0.002 0.004 1000\n", "g.dump", 2500);
    CHECK(d.particles.radius[0] == 0.002);
    CHECK(d.particles.mass[0] == Approx(sphere_mass(0.002, 1000)).epsilon(1e-14));
    CHECK_FALSE(d.velocities);
    // Velocities where all three columns are there (the decks demscale exports dump them).
    const auto v = io::parse_pile("ITEM: ATOMS vz id x y z radius vy type vx\n-3 1 0 0 0.002 0.001 2 1 0.5\n", "v.dump", 2500);
    CHECK(v.velocities);
    CHECK(v.particles.velocity[0] == dem::Vec3(0.5, 2, -3));
}

TEST_CASE("A CSV of spheres is read in metres or millimetres, and demscale's particle state too", "[io][pile]") {
    const auto m = io::parse_pile("r,z,y,x\n0.001,0.002,0,0.005\n", "m.csv", 2000);
    CHECK(m.kind == "csv");
    CHECK(m.particles.position[0].x() == 0.005);
    CHECK(m.particles.radius[0] == 0.001);
    // The header demscale slump writes in slump_particles.csv, with its title line.
    const auto mm = io::parse_pile("# Final particles: x\nx_mm,y_mm,z_mm,radius_mm\n5,0,2,1.25\n", "mm.csv", 2000);
    CHECK(mm.particles.position[0].x() == Approx(0.005).epsilon(1e-15));
    CHECK(mm.particles.radius[0] == Approx(0.00125).epsilon(1e-15));
    // settled.csv of export liggghts: velocities ignored, its own density kept.
    dem::Particles state;
    state.add({0.001, 0.002, 0.003}, 0.0011, 1800, {1, 2, 3});
    const auto file = std::filesystem::temp_directory_path() / "demscale_pile_state_test.csv";
    io::write_particle_state(file, state);
    const auto back = io::read_pile_file("--fill", file.string(), 2500);
    std::filesystem::remove(file);
    CHECK(back.particles.position[0].z() == 0.003);
    CHECK(back.particles.radius[0] == 0.0011);
    CHECK(back.particles.mass[0] == Approx(sphere_mass(0.0011, 1800)).epsilon(1e-12));
}

TEST_CASE("A malformed pile file is refused with its file, line and column", "[io][pile]") {
    const std::string head = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n0 1\nITEM: ATOMS id type x y z radius\n";
    CHECK_THROWS_WITH(io::parse_pile(head + "1 1 0 0 0.001 0.001\n2 1 0 0 abc 0.001\n", "f.dump", 2500),
                      Contains("f.dump:11:5 (z) = abc: accepted a finite number"));
    CHECK_THROWS_WITH(io::parse_pile(head + "1 1 0 0 0.001 0.001\n2 1 0 0 0.003\n", "f.dump", 2500),
                      Contains("f.dump:11:6 = (missing)"));
    CHECK_THROWS_WITH(io::parse_pile(head + "1 1 0 0 0.001 0.001\n2 1 0 0 0.003 -0.001\n", "f.dump", 2500),
                      Contains("f.dump:11:6 (radius) = -0.001: accepted a finite number > 0"));
    CHECK_THROWS_WITH(io::parse_pile(head + "1 1 0 0 0.001 nan\n", "f.dump", 2500), Contains("f.dump:10:6 (radius) = nan"));
    // A dump cut short: fewer rows than its NUMBER OF ATOMS line says.
    CHECK_THROWS_WITH(io::parse_pile(head + "1 1 0 0 0.001 0.001\n", "f.dump", 2500), Contains("1 rows: accepted 2 rows"));
    CHECK_THROWS_WITH(io::parse_pile("ITEM: ATOMS id type xs ys zs\n1 1 0.5 0.5 0.5\n", "s.dump", 2500), Contains("not xs ys zs"));
    CHECK_THROWS_WITH(io::parse_pile("ITEM: ATOMS id type x y z\n1 1 0 0 0\n", "s.dump", 2500), Contains("s.dump:1 (ATOMS columns)"));
    CHECK_THROWS_WITH(io::parse_pile("x,y,z\n0,0,0\n", "c.csv", 2500), Contains("c.csv (header row) = x,y,z"));
    CHECK_THROWS_WITH(io::parse_pile("x,y,z,r\n0,0,1 mm,0.001\n", "c.csv", 2500), Contains("c.csv:2:3 (z) = 1 mm"));
    CHECK_THROWS_WITH(io::parse_pile("x,y,z,r\n", "c.csv", 2500), Contains("(no spheres)"));
}

TEST_CASE("A field is a number only when the whole of it is one", "[io][csv]") {
    CHECK(io::finite_number(" 2 ") == 2.0);
    CHECK(io::finite_number("+1e-3") == 1e-3);
    CHECK(io::finite_number("-0.5") == -0.5);
    for (const char* bad : {"", " ", "1 mm", "nan", "inf", "-inf", "1e999", "0x10", "1,5"}) CHECK_FALSE(io::finite_number(bad));
}
