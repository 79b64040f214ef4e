// cutcell-cli: headless planning, simulation and benchmarks over the CutCell core.
// The command line is declared here with CLI11: every command, its options and the range of
// every value. A command's run function gets its filled options struct (cli_options.h). Any
// usage error (unknown command or option, missing argument, value out of range) exits 64.
#include "cli_commands.h"
#include "option_checks.h"
#include "realtime_options.h"

#include "core/machine/job_importer.h"
#include "core/machine/machine_module.h"

#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>

namespace cutcell::cli {
namespace {

constexpr const char* kExitCodes =
    "exit codes: 0 ok, 1 I/O error, 2 invalid job, 3 path not reachable, 64 usage";

struct AllOptions {
    ValidateOptions validate;
    PlanOptions plan;
    SimulateOptions simulate;
    BenchOptions bench;
    ExportOptions exportFiles;
    RunOptions run;
    DriveSimOptions drivesim;
    HistoryOptions history;
    UsersOptions users;
    AuditOptions audit;
    MachinesOptions machines;
    UpgradeOptions upgrade;
    ShopfloorOptions shopfloor;
    BenchShopfloorOptions bench_shopfloor;
    TuneCommandOptions tune;
    MaterialsOptions materials;
    KinematicsOptions fk, ik;
    CompareOptions compare;
    std::deque<ImportOptions> imports; // one per importer (stable addresses for CLI11)
};

struct Command {
    CLI::App* cmd;
    std::function<int()> run;
};

void addJob(CLI::App& cmd, std::string& job) {
    cmd.add_option("JOB", job, "job file (JSON)")->type_name("FILE")->required();
}

// --devices and the CANopen overrides (simulate and run).
void addDeviceOptions(CLI::App& cmd, DeviceOptions& o) {
    const char* group = "Drives";
    addChoice(cmd, "--devices", o.devices, {"simulated", "canopen"},
              "drives to use (default: the job's devices section)")
        ->group(group);
    cmd.add_option("--can-plugin", o.can.plugin, "Qt CAN bus plugin (default: the job's)")
        ->type_name("P")
        ->group(group);
    cmd.add_option("--can-interface", o.can.interface, "CAN interface (default: the job's)")
        ->type_name("I")
        ->group(group);
    addNumber(
        cmd, "--period-ms", {0.1, 100, "ms"}, [&o](double ms) { o.can.period_s = ms * 1e-3; },
        "SYNC period over CANopen (default: the job's sim.period_s)")
        ->group(group);
    addChoice(
        cmd, "--clock", {"realtime", "fast"},
        [&o](const std::string& c) { o.can.realtime = c == "realtime"; },
        "CANopen cycle paced by the wall clock or lock-step as fast as the bus answers "
        "(default: realtime)")
        ->group(group);
    cmd.add_flag("--drivesim", o.can.in_process_simulator,
                 "start simulated CANopen drives in-process (a peer on the bus)")
        ->group(group);
}

std::vector<Command> declareCommands(CLI::App& app, AllOptions& o) {
    std::vector<Command> commands;
    const auto add = [&](const char* name, const char* description, std::function<int()> run) {
        CLI::App* cmd = app.add_subcommand(name, description);
        commands.push_back({cmd, std::move(run)});
        return cmd;
    };

    CLI::App* validate = add("validate", "check a job file (exit 2 names key, value, unit, limit)",
                             [&] { return runValidate(o.validate); });
    addJob(*validate, o.validate.job);

    CLI::App* plan =
        add("plan", "write the machine's plan files into DIR (path.csv, joints.csv, ...)",
            [&] { return runPlan(o.plan); });
    addJob(*plan, o.plan.job);
    plan->add_option("--out", o.plan.out, "output directory")->type_name("DIR")->required();

    CLI::App* simulate =
        add("simulate", "simulate the cut offline: JSON tracking report (also over CANopen drives)",
            [&] { return runSimulate(o.simulate); });
    addJob(*simulate, o.simulate.job);
    simulate->add_option("--report", o.simulate.report, "write the report here (default: stdout)")
        ->type_name("FILE");
    addChoice(*simulate, "--method", o.simulate.method, {"static_pipe", "rotating_pipe"},
              "cutting method (default: the job's)");
    addDeviceOptions(*simulate, o.simulate.devices);

    CLI::App* bench = add("bench", "measure speed figures (printed, never asserted)",
                          [&] { return runBench(o.bench); });
    bench->add_flag("--json", o.bench.json, "print the figures as JSON");
    bench->add_flag("--quick", o.bench.quick, "fewer repetitions");
    bench->add_option("--job", o.bench.job, "job to measure (default: the built-in job)")
        ->type_name("FILE");
    bench->add_flag("--no-engine", o.bench.no_engine, "skip the motion engine figures");
    bench->add_flag("--no-can", o.bench.no_can, "skip the CANopen figures");
    addRealtimeOptions(*bench, o.bench.rt);

    CLI::App* exportCmd = add("export",
                              "write the files the job's machine offers ('cutcell-cli machines' "
                              "lists them)",
                              [&] { return runExport(o.exportFiles); });
    addJob(*exportCmd, o.exportFiles.job);
    exportCmd->add_option("--gcode", o.exportFiles.gcode, "LinuxCNC G-code, axes X/A")
        ->type_name("FILE");
    exportCmd->add_option("--template-svg", o.exportFiles.template_svg, "cutting template, SVG 1:1")
        ->type_name("FILE");
    exportCmd->add_option("--template-pdf", o.exportFiles.template_pdf, "cutting template, PDF 1:1")
        ->type_name("FILE");
    exportCmd->add_option("--path-csv", o.exportFiles.path_csv, "path with stepper pulses (CSV)")
        ->type_name("FILE");
    exportCmd->add_option("--joints-csv", o.exportFiles.joints_csv, "joint trajectory (CSV)")
        ->type_name("FILE");
    addChoice(*exportCmd, "--paper", o.exportFiles.paper, ExportSettings::papers(),
              "paper of the cutting templates: single = one sheet of the template's size "
              "(default), A4 / A3 = 1:1 tiles with overlap and alignment crosses, one PDF page "
              "each");
    exportCmd->footer("Give at least one of the files.");

    CLI::App* machinesCmd =
        add("machines", "list every machine: id, title, axes (unit, limits, command), exports",
            [&] { return runMachines(o.machines); });
    machinesCmd->add_flag("--json", o.machines.json, "print the list as JSON");

    CLI::App* fk = add("fk", "arm machines: torch tip and direction for joint values (JSON)",
                       [&] { return runFk(o.fk); });
    addJob(*fk, o.fk.job);
    fk->add_option("--arm", o.fk.arm,
                   "the machine's arm (pipe robot: arm; section-steel: path | groove)");
    fk->add_option("--joints", o.fk.values, "joint values in deg, comma-separated")->required();
    CLI::App* ik = add("ik", "arm machines: every IK branch with its status (JSON)",
                       [&] { return runIk(o.ik); });
    addJob(*ik, o.ik.job);
    ik->add_option("--arm", o.ik.arm,
                   "the machine's arm (pipe robot: arm; section-steel: path | groove)");
    ik->add_option("--pose", o.ik.values, "x,y,z (mm),tx,ty,tz (torch direction)")->required();

    CLI::App* compare =
        add("compare",
            "both cutting methods (static and rotating pipe) simulated side by side: table, "
            "time series and figures into DIR",
            [&] { return runCompare(o.compare); });
    addJob(*compare, o.compare.job);
    compare
        ->add_option("--out", o.compare.out,
                     "output directory (default: ./compare-<job stem>): comparison.json, "
                     "comparison.md, the figures as SVG and PNG (written as one unit)")
        ->type_name("DIR");

    // import-<name>: one command per registered importer (MachineModule::importers()).
    for (const JobImporter& importer : jobImporters()) {
        ImportOptions& io = o.imports.emplace_back();
        io.importer = importer.name;
        const std::string name = "import-" + importer.name;
        std::string patterns;
        for (const std::string& p : importer.patterns)
            patterns += (patterns.empty() ? "" : " ") + p;
        CLI::App* imp = add(name.c_str(),
                            (importer.description + " (" + patterns +
                             "); prints what the job "
                             "does not do, line by line")
                                .c_str(),
                            [&io] { return runImport(io); });
        imp->add_option("FILE", io.file,
                        "the file to import, or a folder: every file in it matching " + patterns +
                            " (a batch: one job per piece)")
            ->type_name("FILE|DIR")
            ->required();
        imp->add_option("--out", io.out,
                        "the job file (written atomically); for a folder, the folder the jobs "
                        "and import-report.csv go to")
            ->type_name("JOB.json|DIR")
            ->required();
    }

    CLI::App* tune = add("tune",
                         "the drives' PID gains from the machine's model (pipe robot: SIMC per "
                         "axis): prints them; --out writes the job with them",
                         [&] { return runTune(o.tune); });
    addJob(*tune, o.tune.job);
    tune->add_option("--out", o.tune.out,
                     "write the tuned job here (atomically; give JOB itself to replace it); "
                     "without it nothing is written")
        ->type_name("FILE");
    addNumber(*tune, "--tau-c-ms", o.tune.tau_c_ms, {0.01, 10000, "ms"},
              "desired closed-loop time constant tau_c (default: SIMC's tight tuning, tau_c = "
              "the effective delay theta)");

    CLI::App* materials =
        add("materials",
            "the cut charts (process, material, consumable set: kerf, speed, heights, delays by "
            "thickness) and where their figures come from; --pick one row; --set, --add-row, "
            "--remove-row edit the user's table ($XDG_DATA_HOME/cutcell/cut_charts.json, "
            "a copy of the shipped one at the first edit), which is used instead of the "
            "shipped one when it exists",
            [&] { return runMaterials(o.materials); });
    materials
        ->add_option("--file", o.materials.file,
                     "a cut-chart table to read or edit (default: the user's table when it "
                     "exists, else the shipped one; edits go to the user's table)")
        ->type_name("FILE");
    materials->add_flag("--json", o.materials.json, "print as JSON");
    CLI::Option* pick =
        materials
            ->add_option("--pick", o.materials.pick,
                         "the row for a thickness, interpolated between the chart's rows: PROCESS "
                         "(plasma, oxy_fuel, laser) MATERIAL CONSUMABLE THICKNESS_MM")
            ->expected(4)
            ->type_name("P M C T");
    CLI::Option* setFigure =
        materials
            ->add_option("--set", o.materials.set,
                         "set one figure of the row at THICKNESS_MM: PROCESS MATERIAL CONSUMABLE "
                         "THICKNESS_MM FIGURE (kerf_mm, cut_speed_mm_min, ...) VALUE (C notation: "
                         "2.5)")
            ->expected(6)
            ->type_name("P M C T F V");
    CLI::Option* addRow =
        materials
            ->add_option("--add-row", o.materials.add_row,
                         "add a row: PROCESS MATERIAL CONSUMABLE THICKNESS_MM and FIGURE=VALUE for "
                         "every other column of the chart (cut_speed_mm_min=2500 ...)")
            ->expected(5, -1)
            ->type_name("P M C T F=V...");
    CLI::Option* removeRow =
        materials
            ->add_option("--remove-row", o.materials.remove_row,
                         "remove the row at THICKNESS_MM: PROCESS MATERIAL CONSUMABLE THICKNESS_MM")
            ->expected(4)
            ->type_name("P M C T");
    setFigure->excludes(pick)->excludes(addRow)->excludes(removeRow);
    addRow->excludes(pick)->excludes(removeRow);
    removeRow->excludes(pick);

    CLI::App* upgrade = add("upgrade", "rewrite a schema-1 job file as schema 2",
                            [&] { return runUpgrade(o.upgrade); });
    addJob(*upgrade, o.upgrade.job);
    upgrade->add_option("--out", o.upgrade.out, "the schema-2 job file (written atomically)")
        ->type_name("FILE")
        ->required();

#ifdef CUTCELL_HAVE_DEVICES
    CLI::App* run = add("run",
                        "run the job in the motion engine on simulated or CANopen drives; "
                        "writes a run log",
                        [&] { return runRun(o.run); });
    addJob(*run, o.run.job);
    run->add_flag("--realtime", o.run.realtime, "pace the engine by the wall clock");
    run->add_flag("--quiet", o.run.quiet, "print warnings and faults only");
    addRealtimeOptions(*run, o.run.rt);
    run->add_option("--report", o.run.report, "write the JSON report here (default: stdout)")
        ->type_name("FILE");
    run->add_option("--runs", o.run.runs, "run log directory (default: the job's engine.runs_dir)")
        ->type_name("DIR");
    run->add_option("--record", o.run.record,
                    "add the run to this production record: a SQLite file (the GUI's is "
                    "~/.local/share/cutcell/production.db) or a PostgreSQL connection string "
                    "(postgresql://user@host:port/db)")
        ->type_name("FILE|URL");

    CLI::App* shopfloor =
        add("shopfloor",
            "the cell's Sparkplug B edge node on an MQTT broker (TLS): publishes the cell, idle or "
            "running --run JOB on the simulated rig; takes queued jobs and feed hold from the "
            "network",
            [&] { return runShopfloor(o.shopfloor); });
    shopfloor
        ->add_option("--config", o.shopfloor.config,
                     "the shop-floor configuration (broker, TLS files, user, password file, "
                     "group and edge node ids; devices/shopfloor/README.md)")
        ->type_name("FILE")
        ->required();
    shopfloor->add_option("--run", o.shopfloor.run, "run this job while publishing")
        ->type_name("JOB");
    shopfloor->add_flag("--realtime", o.shopfloor.realtime, "pace the run by the wall clock");
    shopfloor->add_flag("--quiet", o.shopfloor.quiet, "print warnings and faults only");
    addNumber(*shopfloor, "--linger-s", o.shopfloor.linger_s, {0, 86400, "s"},
              "stay connected this long after the run (without --run: 0 = until Ctrl-C or "
              "SIGTERM)");

    CLI::App* benchShopfloor =
        add("bench-shopfloor",
            "measure the shop-floor link against a local Mosquitto broker (TLS): N simulated "
            "cells' messages, bytes, latency and CPU (the broker's too), or --outage: the engine's "
            "timing with the broker killed mid-run and what arrives when it returns",
            [&] { return runBenchShopfloor(o.bench_shopfloor); });
    CLI::Option* cells =
        addInteger(*benchShopfloor, "--cells", o.bench_shopfloor.cells, {1, 1000, ""},
                   "simulated cells, each its own edge node (default 1)");
    CLI::Option* seconds = addNumber(*benchShopfloor, "--seconds", o.bench_shopfloor.seconds,
                                     {1, 3600, "s"}, "the measuring window (default 30)");
    CLI::Option* outage = benchShopfloor->add_flag(
        "--outage", o.bench_shopfloor.outage,
        "run the job three times in real time: without the link, with it, and with the broker "
        "killed a third in and back at two thirds");
    outage->excludes(cells)->excludes(seconds); // a mode's options are refused in the other
    addInteger(*benchShopfloor, "--rounds", o.bench_shopfloor.rounds, {1, 100, ""},
               "--outage: rounds of the three runs, interleaved (default 1; medians printed)")
        ->needs(outage);
    benchShopfloor
        ->add_option("--job", o.bench_shopfloor.job, "--outage: the job (default: the default job)")
        ->type_name("JOB")
        ->needs(outage);
    benchShopfloor->add_flag("--json", o.bench_shopfloor.json, "print the figures as JSON");

    CLI::App* history =
        add("history", "list the runs of the production record (SQLite or PostgreSQL)",
            [&] { return runHistory(o.history); });
    history
        ->add_option("--db", o.history.db,
                     "the record: a SQLite file (default: $XDG_DATA_HOME/cutcell/production.db) "
                     "or a PostgreSQL connection string (postgresql://user@host:port/db)")
        ->type_name("FILE|URL");
    history->add_option("--since", o.history.since, "runs started on or after this day (UTC)")
        ->type_name("YYYY-MM-DD");
    history->add_option("--machine", o.history.machine, "one machine's runs (its id)");
    history->add_option("--outcome", o.history.outcome,
                        "runs with this outcome (completed, aborted, interrupted, ...)");
    history->add_flag("--json", o.history.json, "print the runs as JSON");
    history->add_flag("--csv", o.history.csv, "print the runs as CSV")->excludes("--json");

    CLI::App* users =
        add("users", "the station's users and their levels (production record, Argon2id)",
            [&] { return runUsers(o.users); });
    users
        ->add_option("action", o.users.action,
                     "list, add, remove, passwd (password), level (change the level)")
        ->required()
        ->check(CLI::IsMember({"list", "add", "remove", "passwd", "level"}));
    users->add_option("name", o.users.name, "the user");
    users->add_option("--level", o.users.level,
                      "operator, setter, engineer or administrator (add, level)");
    users->add_option("--admin", o.users.admin,
                      "the administrator who authorises it (password first on standard input)");
    users
        ->add_option("--db", o.users.db,
                     "the record: a SQLite file (default: the GUI's production.db) or a "
                     "PostgreSQL connection string")
        ->type_name("FILE|URL");
    users->footer("Passwords come one per line on standard input (on a terminal: asked without "
                  "echo), the authorising one first. The first user must be an administrator; "
                  "until one exists the station runs without log-in.");

    CLI::App* audit = add("audit", "list the audit trail (who changed what, log-ins, E-STOPs)",
                          [&] { return runAudit(o.audit); });
    audit
        ->add_option("--db", o.audit.db,
                     "the record: a SQLite file (default: the GUI's production.db) or a "
                     "PostgreSQL connection string")
        ->type_name("FILE|URL");
    audit->add_option("--since", o.audit.since, "events on or after this day (UTC)")
        ->type_name("YYYY-MM-DD");
    audit->add_flag("--json", o.audit.json, "print the events as JSON");
    audit->add_flag("--csv", o.audit.csv, "print the events as CSV")->excludes("--json");
    addDeviceOptions(*run, o.run.devices);

    DriveSimOptions& d = o.drivesim;
    CLI::App* drivesim =
        add("drivesim", "CiA 402 drive simulator on a CAN bus, with fault injection",
            [&] { return runDriveSim(o.drivesim); });
    drivesim
        ->add_option("JOB", d.job,
                     "job whose devices section gives the nodes (default: the built-in job)")
        ->type_name("FILE");
    addNodeList(*drivesim, "--nodes", d.nodes_text, d.nodes,
                "node ids, e.g. 1-6, 1,3,5 or 2-3,7 (default: the job's)");
    drivesim->add_option("--plugin", d.plugin, "Qt CAN bus plugin")->type_name("P");
    drivesim->add_option("--interface", d.interface, "CAN interface")->type_name("I");
    addNumber(*drivesim, "--duration", d.duration_s, {0, 1e6, "s"},
              "stop after this long (default 0: at SIGINT/SIGTERM)");
    const char* faults = "Fault injection";
    addInteger(*drivesim, "--fault-node", d.fault_node, {1, 127, ""},
               "node that gets the faults (default: the first)")
        ->group(faults);
    addHex16(*drivesim, "--fault-code", d.fault_code, "an EMCY code",
             "raise this EMCY code (0x0001..0xFFFF)")
        ->group(faults);
    addNumber(*drivesim, "--fault-after", d.fault_after_s, {0, 1e6, "s"},
              "... this long after Operation Enabled")
        ->group(faults);
    addNumber(*drivesim, "--heartbeat-stop-after", d.heartbeat_stop_after_s, {0, 1e6, "s"},
              "stop the heartbeat this long after Operational")
        ->group(faults);
    addNumber(*drivesim, "--following-error-after", d.following_error_after_s, {0, 1e6, "s"},
              "lose the motor torque this long after Operation Enabled")
        ->group(faults);
    addHex16(*drivesim, "--refuse-object", d.refuse_object, "an object index",
             "abort every SDO write to this object (0x06090030), e.g. 0x1017")
        ->group(faults);
#endif
    return commands;
}

// The message of a parse error, naming the command and what was wrong; always exit 64.
int usageError(const CLI::App& app, const CLI::ParseError& e) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    if (parsed.empty()) {
        const std::vector<std::string> extras = app.remaining();
        if (!extras.empty() && extras.front().rfind('-', 0) != 0)
            std::fprintf(stderr, "cutcell-cli: unknown command '%s'\n\n", extras.front().c_str());
        else if (!extras.empty())
            std::fprintf(stderr, "cutcell-cli: %s\n\n", unexpectedArguments(app, extras).c_str());
        else
            std::fprintf(stderr, "cutcell-cli: %s\n\n", e.what());
        std::fputs(app.help().c_str(), stderr);
        return kUsage;
    }
    const CLI::App& cmd = *parsed.front();
    std::string message = e.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
        std::vector<std::string> extras = app.remaining();
        for (const std::string& a : cmd.remaining())
            extras.push_back(a);
        message = unexpectedArguments(cmd, extras);
    }
    std::fprintf(stderr, "cutcell-cli %s: %s\n('cutcell-cli %s --help' lists its options)\n",
                 cmd.get_name().c_str(), message.c_str(), cmd.get_name().c_str());
    return kUsage;
}

} // namespace
} // namespace cutcell::cli

int main(int argc, char** argv) {
    using namespace cutcell::cli;
    CLI::App app("cutcell-cli - headless CutCell: plan, simulate, export and run cutting jobs",
                 "cutcell-cli");
    app.require_subcommand(1);
    // An option given twice takes the later value, so a script can append overrides.
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    app.footer(kExitCodes); // inherited by the commands
    app.get_formatter()->column_width(32);
    AllOptions options;
    const std::vector<Command> commands = declareCommands(app, options);
    app.footer(std::string(kExitCodes) + "\n'cutcell-cli COMMAND --help' lists its options.");

    if (argc < 2) {
        std::fputs(app.help().c_str(), stderr);
        return kUsage;
    }
    // "cutcell-cli help [COMMAND]" as "cutcell-cli [COMMAND] --help".
    if (!std::strcmp(argv[1], "help")) {
        if (argc == 2) {
            std::fputs(app.help().c_str(), stdout);
            return kOk;
        }
        for (const Command& c : commands)
            if (c.cmd->get_name() == argv[2]) {
                std::fputs(c.cmd->help("cutcell-cli").c_str(), stdout);
                return kOk;
            }
        std::fprintf(stderr, "cutcell-cli: unknown command '%s'\n\n%s", argv[2],
                     app.help().c_str());
        return kUsage;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::fputs(app.help().c_str(), stdout); // the help of the command given, if any
        return kOk;
    } catch (const CLI::ParseError& e) {
        return usageError(app, e);
    }
    installUserCutCharts();
    for (const Command& c : commands)
        if (c.cmd->parsed()) return c.run();
    return kUsage;
}
