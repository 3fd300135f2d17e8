#include "io/vtk_writer.hpp"

#include <cstdio>
#include <sstream>

#include "dem/neighbor_list.hpp"
#include "io/atomic_file.hpp"

namespace demscale::io {

std::vector<int> contact_counts(const dem::Particles& p) {
    dem::NeighborList touching(1e-12);
    touching.build(p);
    std::vector<int> n(p.size(), 0);
    for (const auto& [i, j] : touching.pairs())
        if ((p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j]) ++n[i], ++n[j];
    return n;
}

void write_vtp(const std::filesystem::path& file, const dem::Particles& p) {
    std::ostringstream s;
    s.precision(9);
    auto vectors = [&](const char* name, const std::vector<dem::Vec3>& v) {
        s << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto& x : v) s << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
        s << "</DataArray>\n";
    };
    s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << p.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
      << "<Points>\n";
    vectors("position", p.position);
    s << "</Points>\n<PointData Scalars=\"radius\" Vectors=\"velocity\">\n"
      << "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n";
    for (double r : p.radius) s << r << '\n';
    s << "</DataArray>\n";
    vectors("velocity", p.velocity);
    vectors("angular_velocity", p.angular_velocity);
    s << "<DataArray type=\"Int32\" Name=\"species\" format=\"ascii\">\n";
    for (int k : p.species) s << k << '\n';
    s << "</DataArray>\n<DataArray type=\"Int32\" Name=\"contacts\" format=\"ascii\">\n";
    for (int k : contact_counts(p)) s << k << '\n';
    s << "</DataArray>\n</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
    write_file_atomically(file, s.str());
}

void VtkSeries::add(double time, const dem::Particles& p) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%05zu.vtp", pvd_.stem().c_str(), frames_.size());
    write_vtp(pvd_.parent_path() / name, p);
    frames_.emplace_back(time, name);
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (const auto& [t, f] : frames_) s << "<DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
    s << "</Collection>\n</VTKFile>\n";
    write_file_atomically(pvd_, s.str());
}

}  // namespace demscale::io
