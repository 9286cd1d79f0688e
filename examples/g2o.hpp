// g2o pose-graph files for the pose_graph example: VERTEX_SE3:QUAT and EDGE_SE3:QUAT lines, read
// into quat's dual quaternions and written back (the format of the SE-Sync and Ceres data sets).
#pragma once

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <quat/quat.hpp>

namespace g2o {

using quat::dual_quaternion;
using quat::matrix6;
using quat::quaternion;
using quat::vec3;

/// One EDGE_SE3:QUAT: the pose of vertex j seen from vertex i, with the information matrix of the
/// error, ordered (translation, rotation).
struct edge {
    int i, j;
    dual_quaternion<double> measured;
    matrix6<double> information;
};

struct graph {
    std::map<int, dual_quaternion<double>> vertices;  // by id: begin() is the pose held fixed
    std::vector<edge> edges;
};

/// g2o writes x, y, z, qx, qy, qz, qw: the quaternion's scalar LAST. Reads those seven numbers as
/// a unit dual quaternion (normalized, as Ceres's reader does: the file keeps few digits).
inline dual_quaternion<double> read_g2o_pose(std::istream& in) {
    double t[3], q[4];
    in >> t[0] >> t[1] >> t[2] >> q[0] >> q[1] >> q[2] >> q[3];
    return to_dual_quaternion(normalize(quaternion<double>{q[3], q[0], q[1], q[2]}),
                              vec3<double>{t[0], t[1], t[2]});
}

/// Reads VERTEX_SE3:QUAT and EDGE_SE3:QUAT lines (others are skipped): the information's upper
/// triangle, 21 numbers row by row. False if the file cannot be read, a line is malformed, or an
/// edge names a vertex the file does not have.
inline bool read_g2o(const std::string& path, graph& g) {
    std::ifstream file(path);
    if (!file) return false;
    std::string line;
    while (std::getline(file, line)) {
        std::istringstream in(line);
        std::string tag;
        if (!(in >> tag)) continue;  // a blank line
        if (tag == "VERTEX_SE3:QUAT") {
            int id = 0;
            in >> id;
            g.vertices[id] = read_g2o_pose(in);
        } else if (tag == "EDGE_SE3:QUAT") {
            edge e{};
            in >> e.i >> e.j;
            e.measured = read_g2o_pose(in);
            for (int r = 0; r < 6; ++r)
                for (int c = r; c < 6; ++c) {
                    in >> e.information(r, c);
                    e.information(c, r) = e.information(r, c);
                }
            g.edges.push_back(e);
        }
        if (!in) return false;
    }
    for (const edge& e : g.edges)
        if (g.vertices.count(e.i) == 0 || g.vertices.count(e.j) == 0) return false;
    return !g.vertices.empty();
}

inline bool write_g2o(const std::string& path,
                      const std::map<int, dual_quaternion<double>>& poses) {
    std::ofstream out(path);
    for (const auto& [id, x] : poses) {
        const vec3<double> t = translation_of(x);
        char buffer[200];
        std::snprintf(buffer, sizeof buffer,
                      "VERTEX_SE3:QUAT %d %.9f %.9f %.9f %.12f %.12f %.12f %.12f\n", id, t.x, t.y,
                      t.z, x.real.x, x.real.y, x.real.z, x.real.w);
        out << buffer;
    }
    return static_cast<bool>(out);
}

}  // namespace g2o
