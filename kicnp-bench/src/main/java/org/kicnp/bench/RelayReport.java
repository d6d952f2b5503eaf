package org.kicnp.bench;

import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.OptionalDouble;

/** The gateway benchmark's output: the fairness notes, a table per agent count, and the one-line JSON. */
final class RelayReport {
    private RelayReport() {
    }

    /** What was compared and how: printed before the table, so every reader of a result sees the conditions. */
    static String preamble(RelayBenchOptions o, String mosquittoVersion) {
        return String.format(Locale.ROOT, """
                Gateway relay benchmark: K-ICNP GatewayServer vs Mosquitto%s
                  machine: %d cores, load average %s; the clients run in this JVM on the same cores (%d event loops);
                  gateway: %s; I/O threads: %s; socket transport (gateway and clients): %s
                  pattern: agents in pairs, each sends to its peer by name through the hub (K-ICNP relay toAgent; MQTT
                           each client subscribes to its own topic and publishes to its peer's); loopback TCP, Nagle off
                  delivery: K-ICNP fire-and-forget relay (empty id: the hub sends no ack, as the SDK's tellTo) vs
                           MQTT QoS 0 (no acks); %d bytes per message on the wire for both
                  JIT: an untimed %d s closed-loop and %d s open-loop run on each hub first, so the JVMs' hot paths are
                           compiled before measuring
                  throughput: closed loop, %d messages outstanding in total (window per agent shown), %d s after %d s
                           warm-up; msgs/s = messages delivered to agents per second; CPU µs per delivered message
                  latency: open loop, %,d msgs/s in total at a constant rate released by 1 ms ticks, %d s after %d s
                           warm-up; latency = delivery time - intended send time (coordinated omission corrected);
                           over that window, CPU µs per delivered message of the hub and of the client loops, and
                           busy = the share of the whole machine's CPU time (all cores, every process) in use,
                           steal = the share the hypervisor took from this virtual machine (a steal of a few ms on
                           the hub's core stalls every message in flight: the p99 follows it, for both hubs)
                """, mosquittoVersion.isEmpty() ? "" : " (" + mosquittoVersion + ")",
                Runtime.getRuntime().availableProcessors(), loadAverage(), o.clientThreads(), gatewayPlace(o),
                o.gatewayThreads() > 0 ? String.valueOf(o.gatewayThreads()) : "one per core", o.transport().label(),
                o.messageBytes(),
                o.jitWarmup().toSeconds(), o.jitWarmup().isZero() ? 0 : GatewayRelayBench.OPEN_WARMUP.toSeconds(),
                o.outstanding(), o.throughputTime().toSeconds(), o.warmup().toSeconds(), o.rate(),
                o.latencyTime().toSeconds(), o.warmup().toSeconds());
    }

    private static String gatewayPlace(RelayBenchOptions o) {
        if (o.gatewayInProcess()) {
            return "in this JVM, beside the clients (--gateway-in-process)";
        }
        return "a JVM of its own, the launcher's options for `kicnp serve`"
                + (o.gatewayJavaOptions().isEmpty() ? " and the JVM's default collector"
                : " plus " + String.join(" ", o.gatewayJavaOptions()));
    }

    static String loadAverage() {
        try {
            String s = java.nio.file.Files.readString(java.nio.file.Path.of("/proc/loadavg"));
            String[] f = s.split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (java.io.IOException | RuntimeException e) {
            double l = java.lang.management.ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
            return l < 0 ? "unknown" : String.format(Locale.ROOT, "%.2f", l);
        }
    }

    static String table(List<RelayRun> runs, int rate) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                "%-7s %-10s %7s %12s %8s %8s %10s %9s %9s %9s %9s %7s %8s %8s %7s %6s%n", "agents", "hub", "window",
                "msgs/s", "hub CPU", "cli CPU", "delivered", "p50 ms", "p99 ms", "p99.9 ms", "max ms", "lost",
                "hub CPU", "cli CPU", "busy", "steal"));
        sb.append(String.format(Locale.ROOT, "%-7s %-10s %7s %12s %8s %8s %10s %-55s %8s %8s %7s %6s%n", "", "", "",
                "(max)", "µs/msg", "µs/msg", "(open)", "   (open loop at " + String.format(Locale.ROOT, "%,d", rate)
                        + " msgs/s)", "µs/msg", "µs/msg", "%", "%"));
        for (RelayRun r : runs) {
            row(sb, r.agents(), "K-ICNP", r.window(), r.kicnp());
            if (r.mosquitto().isPresent()) {
                row(sb, r.agents(), "Mosquitto", r.window(), r.mosquitto().get());
            } else {
                sb.append(String.format(Locale.ROOT, "%-7d %-10s %s%n", r.agents(), "Mosquitto", r.note().orElse("")));
            }
            r.ratio().ifPresent(x -> sb.append(String.format(Locale.ROOT,
                    "%-7d ratio K-ICNP / Mosquitto throughput: %.2f%n", r.agents(), x)));
        }
        return sb.toString();
    }

    private static void row(StringBuilder sb, int agents, String hub, int window, HubFigures f) {
        LatencyFigures l = f.latency();
        sb.append(String.format(Locale.ROOT,
                "%-7d %-10s %7d %,12.0f %8.1f %8.1f %,10.0f %9.3f %9.3f %9.3f %9.3f %7d %8.1f %8.1f %7.0f %6.1f%s%n",
                agents, hub, window, f.msgsPerSecond(), f.hubCpuMicrosPerMsg(), f.clientCpuMicrosPerMsg(),
                l.deliveredPerSecond(), l.p50Millis(), l.p99Millis(), l.p999Millis(), l.maxMillis(), l.lost(),
                l.hubCpuMicrosPerMsg(), l.clientCpuMicrosPerMsg(), l.machineBusyPercent(), l.machineStealPercent(),
                f.shed() > 0 ? "  (hub shed " + f.shed() + ")" : ""));
    }

    /**
     * The kernel's floor under the figures above: a relayed message is two loopback hops, so twice the measured hop is
     * the least CPU per message any hub and its clients together can spend here, and at the offered rate that least is
     * a share of the machine no hub can go below.
     */
    static String floor(double hopMicros, RelayBenchOptions o) {
        return String.format(Locale.ROOT, """
                kernel floor: one loopback TCP hop of %d bytes (write + read, one thread, no wake-up) costs %.2f µs of CPU
                           here (measured after the runs); a relayed message takes two, %.2f µs, so at %,d msgs/s the
                           hops alone keep %.0f %% of the machine busy, whatever the hub (hub + clients µs/msg above
                           include them)
                """, o.messageBytes(), hopMicros, 2 * hopMicros, o.rate(), floorBusyPercent(hopMicros, o));
    }

    private static double floorBusyPercent(double hopMicros, RelayBenchOptions o) {
        return 2 * hopMicros * o.rate() / 1e6 / Runtime.getRuntime().availableProcessors() * 100;
    }

    /**
     * The last line: {@code {"runs": [{"agents": ..., "kicnp_msgs_per_s": ..., ...}, ...], ...}}, with the loopback
     * hop's cost and the busy share it sets at the offered rate (null when it could not be measured).
     */
    static String json(List<RelayRun> runs, RelayBenchOptions o, OptionalDouble hopMicros) {
        StringBuilder sb = new StringBuilder("{\"runs\": [");
        for (int i = 0; i < runs.size(); i++) {
            RelayRun r = runs.get(i);
            LatencyFigures k = r.kicnp().latency();
            Optional<LatencyFigures> m = r.mosquitto().map(HubFigures::latency);
            sb.append(i == 0 ? "" : ", ").append("{\"agents\": ").append(r.agents())
                    .append(", \"kicnp_msgs_per_s\": ").append(num(r.kicnp().msgsPerSecond(), 0))
                    .append(", \"mosquitto_msgs_per_s\": ").append(opt(r.mosquitto().map(HubFigures::msgsPerSecond), 0))
                    .append(", \"ratio\": ").append(opt(r.ratio(), 3))
                    .append(", \"kicnp_p99_ms_at_50k\": ").append(num(k.p99Millis(), 3))
                    .append(", \"kicnp_hub_cpu_us_per_msg\": ").append(num(r.kicnp().hubCpuMicrosPerMsg(), 2))
                    .append(", \"mosquitto_hub_cpu_us_per_msg\": ")
                    .append(opt(r.mosquitto().map(HubFigures::hubCpuMicrosPerMsg), 2))
                    .append(", \"kicnp_p50_ms_at_50k\": ").append(num(k.p50Millis(), 3))
                    .append(", \"kicnp_p999_ms_at_50k\": ").append(num(k.p999Millis(), 3))
                    .append(", \"kicnp_lost_at_50k\": ").append(k.lost())
                    .append(", \"mosquitto_p50_ms_at_50k\": ").append(opt(m.map(LatencyFigures::p50Millis), 3))
                    .append(", \"mosquitto_p99_ms_at_50k\": ").append(opt(m.map(LatencyFigures::p99Millis), 3))
                    .append(", \"mosquitto_p999_ms_at_50k\": ").append(opt(m.map(LatencyFigures::p999Millis), 3))
                    .append(", \"mosquitto_lost_at_50k\": ").append(m.map(x -> String.valueOf(x.lost())).orElse("null"))
                    .append(", \"kicnp_hub_cpu_us_per_msg_at_50k\": ").append(num(k.hubCpuMicrosPerMsg(), 2))
                    .append(", \"kicnp_busy_pct_at_50k\": ").append(num(k.machineBusyPercent(), 1))
                    .append(", \"kicnp_steal_pct_at_50k\": ").append(num(k.machineStealPercent(), 2))
                    .append(", \"mosquitto_hub_cpu_us_per_msg_at_50k\": ")
                    .append(opt(m.map(LatencyFigures::hubCpuMicrosPerMsg), 2))
                    .append(", \"mosquitto_busy_pct_at_50k\": ").append(opt(m.map(LatencyFigures::machineBusyPercent), 1))
                    .append(", \"mosquitto_steal_pct_at_50k\": ").append(opt(m.map(LatencyFigures::machineStealPercent), 2))
                    .append('}');
        }
        return sb.append("], \"offered_msgs_per_s\": ").append(o.rate())
                .append(", \"message_bytes\": ").append(o.messageBytes())
                .append(", \"gateway\": \"").append(o.gatewayInProcess() ? "in_process" : "own_process").append('"')
                .append(", \"transport\": \"").append(o.transport().label()).append('"')
                .append(", \"cores\": ").append(Runtime.getRuntime().availableProcessors())
                .append(", \"loopback_hop_us\": ")
                .append(hopMicros.isPresent() ? num(hopMicros.getAsDouble(), 2) : "null")
                .append(", \"floor_busy_pct_at_rate\": ")
                .append(hopMicros.isPresent() ? num(floorBusyPercent(hopMicros.getAsDouble(), o), 1) : "null")
                .append(", \"load_average\": \"").append(loadAverage()).append("\"}").toString();
    }

    private static String num(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    private static String opt(Optional<Double> v, int decimals) {
        return v.map(x -> num(x, decimals)).orElse("null");
    }
}
