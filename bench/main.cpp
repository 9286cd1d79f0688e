// quat_bench: Google Benchmark of quat against GLM and Eigen.
//   quat_bench [benchmark flags]   every benchmark, Google Benchmark's console/JSON output
//   quat_bench --table             short runs (min time 0.05 s each), 7 repetitions in random
//                                  interleaved order, printed as medians side by side with their
//                                  spread, copies against the fastest copy (the floor), targets
//   quat_bench --counts            the thesis's operation-count tables beside ours (no timing)
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "build_info.hpp"
#include "common.hpp"

namespace {

struct measurement {
    std::string operation, library, representation, type, size;
    double ns_per_item = 0;  // the median over the repetitions
    double spread = 0;       // (slowest - fastest) / median over the repetitions
};

// Splits "<operation>/<library>/<representation>/<type>[/<n>]".
measurement parse(const std::string& name) {
    std::vector<std::string> part;
    std::size_t start = 0;
    for (std::size_t slash; (slash = name.find('/', start)) != std::string::npos; start = slash + 1)
        part.push_back(name.substr(start, slash - start));
    part.push_back(name.substr(start));
    part.resize(5);
    return {part[0], part[1], part[2], part[3], part[4], 0, 0};
}

/// Keeps every repetition instead of printing it; the table of medians is printed afterwards.
class collecting_reporter : public benchmark::BenchmarkReporter {
public:
    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            if (run.run_type != Run::RT_Iteration || run.error_occurred) continue;
            const auto items = run.counters.find("items_per_second");
            if (items == run.counters.end() || !(items->second.value > 0)) continue;
            // items_per_second is per CPU second; CPU time is also what the table shows, because on
            // a shared machine the real time includes other processes' turns.
            const std::string name = run.benchmark_name();
            // With repetitions the name carries no suffix; per-repetition names are the same.
            if (samples_.find(name) == samples_.end()) order_.push_back(name);
            samples_[name].push_back(1e9 / items->second.value);
            std::fprintf(stderr, ".");
        }
    }
    // One measurement per benchmark: the median of its repetitions and their spread.
    std::vector<measurement> results() const {
        std::vector<measurement> all;
        for (const std::string& name : order_) {
            std::vector<double> v = samples_.at(name);
            std::sort(v.begin(), v.end());
            const std::size_t k = v.size();
            measurement m = parse(name);
            m.ns_per_item = k % 2 ? v[k / 2] : (v[k / 2 - 1] + v[k / 2]) / 2;
            m.spread = m.ns_per_item > 0 ? (v.back() - v.front()) / m.ns_per_item : 0;
            all.push_back(m);
        }
        return all;
    }

    int repetitions() const {
        std::size_t most = 0;
        for (const auto& entry : samples_) most = std::max(most, entry.second.size());
        return static_cast<int>(most);
    }

private:
    std::vector<std::string> order_;
    std::map<std::string, std::vector<double>> samples_;
};

std::string row_key(const measurement& m) {
    return m.operation + "/" + m.representation + "/" + m.type +
           (m.size.empty() ? "" : "/" + m.size);
}

const measurement* find_measurement(const std::vector<measurement>& all, const std::string& name) {
    const measurement key = parse(name);
    for (const measurement& m : all)
        if (m.operation == key.operation && m.library == key.library &&
            m.representation == key.representation && m.type == key.type && m.size == key.size)
            return &m;
    return nullptr;
}

double find(const std::vector<measurement>& all, const std::string& name) {
    const measurement* m = find_measurement(all, name);
    return m ? m->ns_per_item : 0;
}

// The copies of the same bytes (bench::register_copy_floors) and the fastest of them, per size.
const char* const copy_kinds[] = {"memcpy", "copy_loop", "stream"};

struct copy_floor {
    double ns = 0;
    std::string by;  // which copy set it
};

copy_floor find_floor(const std::vector<measurement>& all, const std::string& operation,
                      const std::string& size) {
    copy_floor best;
    for (const char* kind : copy_kinds) {
        const double t = find(all, operation + "/" + kind + "/bytes/float/" + size);
        if (t > 0 && (best.ns == 0 || t < best.ns)) best = {t, kind};
    }
    return best;
}

void print_table(const std::vector<measurement>& all, int repetitions) {
    std::vector<std::string> order;
    std::map<std::string, std::map<std::string, const measurement*>> rows;
    for (const measurement& m : all) {
        const std::string key = row_key(m);
        if (rows.find(key) == rows.end()) order.push_back(key);
        rows[key][m.library] = &m;
    }
    std::printf(
        "\nns per item (per point, product, value or call; CPU time), median of %d interleaved "
        "repetitions; ratio = other / quat, > 1 means quat is faster; spread = (slowest - fastest) "
        "/ median, the largest in the row\n",
        repetitions);
    std::printf("%-52s %10s %10s %10s %9s %9s %7s\n", "operation/representation/type[/n]", "quat",
                "glm", "eigen", "glm/quat", "eigen/quat", "spread");
    auto cell = [](const std::map<std::string, const measurement*>& r, const char* lib) {
        const auto it = r.find(lib);
        return it == r.end() ? std::string("-")
                             : std::to_string(it->second->ns_per_item).substr(0, 8);
    };
    for (const std::string& key : order) {
        const auto& r = rows[key];
        double spread = 0;
        for (const auto& entry : r) spread = std::max(spread, entry.second->spread);
        char spread_text[16];
        std::snprintf(spread_text, sizeof spread_text, "%.0f%%", 100 * spread);
        if (!r.count("quat") && !r.count("glm") && !r.count("eigen")) {
            // A row of copies: each copy, and which one is the floor.
            std::string text;
            const measurement* fastest = nullptr;
            for (const char* kind : copy_kinds) {
                if (!r.count(kind)) continue;
                text += std::string("  ") + kind + " " + cell(r, kind);
                if (!fastest || r.at(kind)->ns_per_item < fastest->ns_per_item)
                    fastest = r.at(kind);
            }
            if (fastest) text += "  floor: " + fastest->library;
            std::printf("%-52s %7s%s\n", key.c_str(), spread_text, text.c_str());
            continue;
        }
        const double q = r.count("quat") ? r.at("quat")->ns_per_item : 0;
        auto ratio = [&](const char* lib) {
            return (q > 0 && r.count(lib)) ? std::to_string(r.at(lib)->ns_per_item / q).substr(0, 6)
                                           : std::string("-");
        };
        std::printf("%-52s %10s %10s %10s %9s %9s %7s\n", key.c_str(), cell(r, "quat").c_str(),
                    cell(r, "glm").c_str(), cell(r, "eigen").c_str(), ratio("glm").c_str(),
                    ratio("eigen").c_str(), spread_text);
    }
}

// The widest instruction set this binary was compiled for: the one quat's batch code was built for
// (its batch functions live in an inline namespace per instruction set).
constexpr const char* instruction_set =
#if defined(__AVX512F__)
    "AVX-512";
#elif defined(__AVX2__) && defined(__FMA__)
    "AVX2 + FMA";
#elif defined(__AVX2__)
    "AVX2";
#elif defined(__AVX__)
    "AVX";
#else
    "SSE2";
#endif
#if defined(__AVX2__)
constexpr bool wide_vectors = true;  // x86-64-v3 or native: where the in-cache goals apply
#else
constexpr bool wide_vectors = false;
#endif

// The fastest of the peers' (GLM's and Eigen's) plain loops, for one benchmark and size.
double best_peer(const std::vector<measurement>& all, const std::string& operation,
                 const std::vector<std::string>& representations, const std::string& size) {
    double best = 0;
    for (const char* lib : {"glm", "eigen"})
        for (const std::string& rep : representations) {
            const double t = find(all, operation + "/" + lib + "/" + rep + "/float/" + size);
            if (t > 0 && (best == 0 || t < best)) best = t;
        }
    return best;
}

// The targets of the speed issues, each a ratio from this one run. Goals marked "wide" are set for
// AVX2 and AVX-512 builds; a plain x86-64 build prints their ratios for information.
void print_targets(const std::vector<measurement>& all) {
    std::printf("\nspeed targets (float; instruction set %s)\n", instruction_set);
    auto target = [](const std::string& what, double value, double goal, bool at_least,
                     bool wide_only = false) {
        if (!(value > 0)) return std::printf("  %-62s not measured\n", what.c_str()), void();
        const bool met = at_least ? value >= goal : value <= goal;
        const char* verdict = met                          ? "met"
                              : wide_only && !wide_vectors ? "(AVX2/AVX-512 goal)"
                                                           : "MISSED";
        std::printf("  %-62s %7.2f  (goal %s %.2f)  %s\n", what.c_str(), value,
                    at_least ? ">=" : "<=", goal, verdict);
    };
    auto ratio = [](double numerator, double denominator) {
        return numerator > 0 && denominator > 0 ? numerator / denominator : 0;
    };
    // Copies are compared with the floor: the fastest of memcpy, a plain loop and (beyond the
    // last-level cache) a streaming copy of the same bytes, named after the ratio.
    auto floor_text = [](const copy_floor& f) { return f.by.empty() ? std::string("copy") : f.by; };
    for (const char* n : {"1024", "4194304"}) {
        const std::string size = n;
        const bool in_cache = size == "1024";
        const copy_floor copy = find_floor(all, "rotate_batch", size);
        const double peer = best_peer(all, "rotate_batch", {"quaternion", "matrix"}, size);
        for (const char* rep : {"quaternion", "quaternion_soa"}) {
            const std::string r = rep;
            const double ours = find(all, "rotate_batch/quat/" + r + "/float/" + size);
            target("rotate_batch " + size + " " + r + ": quat / floor (" + floor_text(copy) + ")",
                   ratio(ours, copy.ns), in_cache ? 1.2 : 1.10, false, in_cache);
            if (in_cache)
                target("rotate_batch 1024 " + r + ": best(glm, eigen) / quat", ratio(peer, ours),
                       r == "quaternion" && wide_vectors ? 1.3 : 1.0, true);
            else
                target("rotate_batch " + size + " " + r + ": best(glm, eigen) / quat",
                       ratio(peer, ours), 1.0, true);
        }
    }
    // The same job for every library: rotating by a quaternion (the peers' quaternion loops, or
    // their matrix formed once and their matrix loop), and by a ready matrix.
    for (const char* n : {"64", "1024"}) {
        const std::string size = n;
        target("rotate_batch " + size + " quaternion: peers from a quaternion / quat",
               ratio(best_peer(all, "rotate_batch", {"quaternion", "quaternion_via_matrix"}, size),
                     find(all, "rotate_batch/quat/quaternion/float/" + size)),
               1.0, true);
        target("rotate_batch " + size + " matrix: best(glm, eigen) / quat",
               ratio(best_peer(all, "rotate_batch", {"matrix"}, size),
                     find(all, "rotate_batch/quat/matrix/float/" + size)),
               1.0, true);
    }
    // Per-element batches: the array-of-structs form at its shuffle bound (about 1.6x by the uop
    // count in docs/performance.md), the struct-of-arrays form, which needs no shuffles, twice the
    // peers' array-of-structs loops.
    for (const char* operation : {"rotate_each", "compose_each"}) {
        const std::string op = operation;
        const double ours = find(all, op + "/quat/quaternion/float/1024");
        const double soa = find(all, op + "/quat/quaternion_soa/float/1024");
        for (const char* lib : {"glm", "eigen"}) {
            const double theirs = find(all, op + "/" + lib + "/quaternion/float/1024");
            target(op + " 1024: " + lib + " / quat", ratio(theirs, ours), 1.5, true, true);
            if (soa > 0)
                target(op + " 1024: " + lib + " / quat struct of arrays", ratio(theirs, soa), 2.0,
                       true, true);
        }
    }
    // The requirement of every batch and per-element entry point: at least as fast as the fastest
    // peer loop for the same job, at 64 elements (the call and the tail), 1024 (in cache) and 4M
    // (beyond the last-level cache); struct-of-arrays forms against the peers' arrays of structs.
    struct job {
        const char* operation;
        const char* representation;
        std::vector<std::string> peers;  // the peers' representations doing the same job
    };
    const job jobs[] = {{"rotate_each", "quaternion", {"quaternion"}},
                        {"rotate_each", "quaternion_soa", {"quaternion"}},
                        {"compose_each", "quaternion", {"quaternion"}},
                        {"to_matrix_each", "quaternion", {"quaternion"}},
                        {"to_quaternion_each", "matrix", {"matrix"}},
                        {"slerp_batch", "quaternion", {"quaternion"}}};
    for (const job& j : jobs)
        for (const char* n : {"64", "1024", "4194304"}) {
            const std::string op = j.operation, size = n;
            const double ours = find(all, op + "/quat/" + j.representation + "/float/" + size);
            if (!(ours > 0)) continue;
            target(op + " " + size + " " + j.representation + ": best(glm, eigen) / quat",
                   ratio(best_peer(all, op, j.peers, size), ours), 1.0, true);
        }
    const double chain = find(all, "chain/quat/quaternion/float/1024");
    target("chain 1024: glm / quat compose(span)",
           ratio(find(all, "chain/glm/quaternion/float/1024"), chain), 1.5, true);
    const double slerp = find(all, "slerp/quat/quaternion/float"),
                 glm_slerp = find(all, "slerp/glm/quaternion/float");
    target("slerp: quat / glm", ratio(slerp, glm_slerp), 1.0, false);
    const double batch = find(all, "slerp_batch/quat/quaternion/float/1024");
    target("slerp_batch 1024: glm per-call slerp / quat per value", ratio(glm_slerp, batch), 4.0,
           true);
    target("slerp_fast eberly (<= 1e-6 rad): glm slerp / quat",
           ratio(glm_slerp, find(all, "slerp_fast/quat/eberly/float")), 3.0, true);
    target("slerp_fast corrected_nlerp (<= 1e-3 rad): glm slerp / quat",
           ratio(glm_slerp, find(all, "slerp_fast/quat/corrected_nlerp/float")), 5.0, true);

    // Point-set registration: Eigen's umeyama on the same points, and one read of them.
    for (const char* n : {"4", "64", "4096"}) {
        const std::string size = n;
        target("align_points " + size + ": eigen umeyama / quat",
               ratio(find(all, "align_points/eigen/vec3/float/" + size),
                     find(all, "align_points/quat/vec3/float/" + size)),
               1.0, true);
    }
    target("align_points 4096: quat / read_input",
           ratio(find(all, "align_points/quat/vec3/float/4096"),
                 find(all, "align_points/read_input/vec3/float/4096")),
           2.0, false);

    // Rigid motions. The copy floor is rotate_batch's: it copies the same 24 bytes per point.
    const copy_floor copy = find_floor(all, "rotate_batch", "4194304");
    const copy_floor copy_small = find_floor(all, "rotate_batch", "1024");
    const double peer_out =
        best_peer(all, "transform_batch", {"dual_quaternion", "matrix"}, "4194304");
    for (const char* rep : {"dual_quaternion", "matrix", "dual_quaternion_soa"}) {
        const std::string r = rep;
        const double ours = find(all, "transform_batch/quat/" + r + "/float/4194304");
        target("transform_batch 4194304: quat " + r + " / floor (" + floor_text(copy) + ")",
               ratio(ours, copy.ns), 1.10, false);
        target("transform_batch 4194304: best(glm, eigen) / quat " + r, ratio(peer_out, ours), 1.0,
               true);
    }
    // 64 points by representation, as rotate_batch's 64-point rows: a dual quaternion against the
    // peers' loops over one (quat converts it to a matrix inside the call, which 64 points do not
    // hide), a matrix against the peers' matrix loops.
    for (const char* rep : {"dual_quaternion", "matrix"}) {
        const std::string r = rep;
        target("transform_batch 64 " + r + ": peers from a " + r + " / quat",
               ratio(best_peer(all, "transform_batch", {r}, "64"),
                     find(all, "transform_batch/quat/" + r + "/float/64")),
               1.0, true);
    }
    const double moved = find(all, "transform_batch/quat/dual_quaternion/float/1024");
    target("transform_batch 1024: best(glm, eigen) / quat",
           ratio(best_peer(all, "transform_batch", {"dual_quaternion", "matrix"}, "1024"), moved),
           1.0, true);
    target("rigid_chain 1024: glm mat4 / quat compose(span)",
           ratio(find(all, "rigid_chain/glm/matrix/float/1024"),
                 find(all, "rigid_chain/quat/dual_quaternion/float/1024")),
           1.5, true);
    // Estimation (double): each analytic Jacobian against ceres::Jet autodiff of the same
    // function, and SO(3)'s exp and log against the conversions they call (the same work: the
    // 5 % leaves room for the noise of a shared machine).
    for (const char* operation :
         {"so3_exp", "so3_log", "so3_compose", "so3_act", "se3_exp", "se3_log", "se3_between"}) {
        const std::string op = operation;
        target("jacobian " + op + " (double): jet / quat",
               ratio(find(all, "jacobian/jet/" + op + "/double"),
                     find(all, "jacobian/quat/" + op + "/double")),
               5.0, true);
    }
    target("so3::exp (double): quat / from_rotation_vector",
           ratio(find(all, "so3/exp/double"), find(all, "so3/from_rotation_vector/double")), 1.05,
           false);
    target("so3::log (double): quat / to_rotation_vector",
           ratio(find(all, "so3/log/double"), find(all, "so3/to_rotation_vector/double")), 1.05,
           false);
    // In cache the copy is not a bound, only a scale: how many copies one transform costs.
    if (moved > 0 && copy_small.ns > 0)
        std::printf("  %-62s %7.2f  (information)\n",
                    ("transform_batch 1024: quat / floor (" + floor_text(copy_small) + ")").c_str(),
                    moved / copy_small.ns);

    std::printf(
        "\napply_chain (k = 8 rotations on n points, ns per point): composed first vs applied one "
        "by one\n");
    std::printf("  %-6s %-8s %12s %12s %12s %12s  fastest\n", "n", "library", "quat.comp",
                "matrix.comp", "quat.each", "matrix.each");
    for (const char* lib : {"quat", "glm", "eigen"})
        for (const char* n : {"1", "2", "4", "8", "16", "64", "256"}) {
            const std::string l = lib, s = n;
            const double v[4] = {find(all, "apply_chain_composed/" + l + "/quaternion/float/" + s),
                                 find(all, "apply_chain_composed/" + l + "/matrix/float/" + s),
                                 find(all, "apply_chain_each/" + l + "/quaternion/float/" + s),
                                 find(all, "apply_chain_each/" + l + "/matrix/float/" + s)};
            if (!(v[0] > 0)) continue;
            const char* names[4] = {"quaternion composed", "matrix composed", "quaternion each",
                                    "matrix each"};
            int fastest = 0;
            for (int i = 1; i < 4; ++i)
                if (v[i] > 0 && v[i] < v[fastest]) fastest = i;
            std::printf("  %-6s %-8s %12.2f %12.2f %12.2f %12.2f  %s\n", n, lib, v[0], v[1], v[2],
                        v[3], names[fastest]);
        }
}

// The CPU as /proc/cpuinfo names it, with its vendor, family and model numbers (a virtual machine
// may name only "AMD EPYC"; the family tells Zen 4, 25, from Zen 5, 26); "unknown" elsewhere.
std::string cpu_description() {
    std::ifstream info("/proc/cpuinfo");
    std::string line, name, vendor, family, model;
    auto value = [](const std::string& l) {
        const std::size_t colon = l.find(':');
        return colon == std::string::npos || colon + 2 > l.size() ? std::string()
                                                                  : l.substr(colon + 2);
    };
    while (std::getline(info, line) && (name.empty() || family.empty() || model.empty())) {
        if (line.rfind("model name", 0) == 0) name = value(line);
        else if (line.rfind("vendor_id", 0) == 0) vendor = value(line);
        else if (line.rfind("cpu family", 0) == 0) family = value(line);
        else if (line.rfind("model\t", 0) == 0) model = value(line);
    }
    if (name.empty()) return "unknown";
    // Appended piecewise: GCC 12's -Wrestrict misfires on chains of std::string + at -O3.
    std::string text = name;
    text += " (";
    text += vendor;
    text += " family ";
    text += family;
    text += " model ";
    text += model;
    text += ')';
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    bool table = false, counts = false, has_min_time = false, has_repetitions = false,
         has_interleaving = false;
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--table") table = true;
        else if (a == "--counts") counts = true;
        else args.push_back(argv[i]);
        if (a.rfind("--benchmark_min_time", 0) == 0) has_min_time = true;
        if (a.rfind("--benchmark_repetitions", 0) == 0) has_repetitions = true;
        if (a.rfind("--benchmark_enable_random_interleaving", 0) == 0) has_interleaving = true;
    }
    if (counts) return bench::print_counts();
    // The table: short runs, repeated 7 times in random order, each cell the median, so that one
    // run disturbed by another process on a shared machine cannot flip a verdict (7: the speed
    // issue's protocol, a target met by the median over three runs of 7). Each flag may be given
    // to override it.
    static char short_run[] = "--benchmark_min_time=0.05";
    static char repeated[] = "--benchmark_repetitions=7";
    static char interleaved[] = "--benchmark_enable_random_interleaving=true";
    if (table && !has_min_time) args.push_back(short_run);
    if (table && !has_repetitions) args.push_back(repeated);
    if (table && !has_interleaving) args.push_back(interleaved);
    int count = static_cast<int>(args.size());
    args.push_back(nullptr);

    benchmark::AddCustomContext("quat_compiler", bench::build_info::compiler);
    benchmark::AddCustomContext("quat_compile_flags", bench::build_info::flags);
    benchmark::AddCustomContext("quat_march", bench::build_info::arch);
    benchmark::AddCustomContext("quat_instruction_set", instruction_set);
    benchmark::AddCustomContext("quat_commit", bench::build_info::commit);
    benchmark::AddCustomContext("quat_cpu", cpu_description());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
    bench::register_rotate();
    bench::register_compose();
    bench::register_conversions();
    bench::register_interpolation();
    bench::register_motion();
    bench::register_align();
    bench::register_estimation();
    bench::register_keyframes();
    bench::register_rigid();
    bench::register_each();
    bench::register_lie();
    bench::register_trajectory();
    if (!table) {
        benchmark::RunSpecifiedBenchmarks();
    } else {
        collecting_reporter reporter;
        std::printf(
            "compiler: %s\nflags: %s\ninstruction set: %s (-march=%s)\ncpu: %s\ncommit: %s\n",
            bench::build_info::compiler, bench::build_info::flags, instruction_set,
            *bench::build_info::arch ? bench::build_info::arch : "compiler default",
            cpu_description().c_str(), bench::build_info::commit);
        benchmark::RunSpecifiedBenchmarks(&reporter);
        const std::vector<measurement> results = reporter.results();
        print_table(results, reporter.repetitions());
        print_targets(results);
    }
    benchmark::Shutdown();
    return 0;
}
