#include "sim_esc/soem_session.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/shell_words.hpp"
#include "support/test_support.hpp"

namespace esi::test {

std::string soem_unavailable() {
    const std::string master = ESI_SOEM_MASTER;
    if (master.empty() || !std::filesystem::exists(master))
        return "the SOEM test master was not built (../shared/tools/soem absent)";
    static const std::string namespaces = [] {
        const RunResult r = run({"unshare", "-rn", "sh", "-c", "ip link add v0 type veth peer name v1 && ip link set v0 up"});
        if (r.exit_code != 0) return "user/network namespaces with a veth pair are refused here: " + r.err;
        return std::string();
    }();
    return namespaces;
}

std::vector<SoemStepResult> run_soem_session(const std::vector<SoemStep>& steps) {
    TempDir dir;
    std::ostringstream script;
    script << "ip link add v0 type veth peer name v1 && ip link set v0 up && ip link set v1 up || exit 3\n";
    const std::string sim = tool("esi-sim").string();
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const std::string out = (dir.path() / std::to_string(i)).string();
        script << shell_quoted(sim) << " --iface v1" << shell_arguments(steps[i].sim_args) << " 2> " << shell_quoted(out + ".err") << " &\n"
               << "pid=$!\n"
               << "n=0; while ! grep -q 'slave(s) on' " << shell_quoted(out + ".err")
               << " 2>/dev/null && kill -0 $pid 2>/dev/null && [ $n -lt 400 ]; do sleep 0.025; n=$((n+1)); done\n"
               << "if kill -0 $pid 2>/dev/null; then timeout 120 " << shell_quoted(ESI_SOEM_MASTER) << " v0"
               << shell_arguments(steps[i].master_args) << " > " << shell_quoted(out + ".json") << " 2> /dev/null; kill -TERM $pid; fi\n"
               << "wait $pid; echo $? > " << shell_quoted(out + ".rc") << "\n";
    }
    const RunResult r = run({"unshare", "-rn", "sh", "-c", script.str()});
    std::vector<SoemStepResult> results(steps.size());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const std::filesystem::path out = dir.path() / std::to_string(i);
        SoemStepResult& result = results[i];
        if (std::filesystem::exists(out.string() + ".err")) result.sim_stderr = read_text(out.string() + ".err");
        if (std::filesystem::exists(out.string() + ".rc")) result.sim_exit = std::stoi("0" + read_text(out.string() + ".rc"));
        if (std::filesystem::exists(out.string() + ".json")) {
            result.master_output = read_text(out.string() + ".json");
            const auto parsed = nlohmann::json::parse(result.master_output, nullptr, false);
            if (!parsed.is_discarded()) result.report = parsed;
        }
    }
    if (r.exit_code != 0 && results.empty()) results.push_back({});
    return results;
}

}  // namespace esi::test
