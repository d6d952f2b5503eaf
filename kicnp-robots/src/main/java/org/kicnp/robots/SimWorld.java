package org.kicnp.robots;

import com.fasterxml.jackson.databind.JsonNode;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * The simulated room: the Python simulator ({@code robots-sim}) running as a subprocess, spoken to in JSON lines.
 * Requests get fresh ids and futures that complete with their ack (or fail with the simulator's error, a timeout,
 * or its death); commands are followed as {@link SimAction}s; every event goes to the listeners in stream order on
 * one event thread. When the process dies (exit, kill, broken pipe) every request and action in flight fails with a
 * reason such as {@code simulator exited with code 137}, listeners get {@link SimEvent.Exited}, and every later
 * call throws {@link SimulatorExitedException} at once. In real time a simulator that answers no request within the
 * request timeout (pinged while actions run and it is quiet) is hung: it is stopped and treated as dead.
 */
public final class SimWorld implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(SimWorld.class);
    /** The version of the simulator protocol this class speaks (robots-sim/PROTOCOL.md). */
    public static final String PROTOCOL = "kicnp-sim/1";

    private final SimOptions options;
    private final SimProcess process;
    private final SimCodec codec = new SimCodec();
    private final AtomicLong ids = new AtomicLong();
    private final Map<String, CompletableFuture<Optional<JsonNode>>> pending = new ConcurrentHashMap<>();
    private final Map<String, CompletableFuture<JsonNode>> queries = new ConcurrentHashMap<>();
    private final Map<String, SimAction> actions = new ConcurrentHashMap<>();
    /** Where events and action updates go, in stream order, off the reader thread. */
    private final SimEventThread events = new SimEventThread(actions);
    private final CompletableFuture<SimEvent.Hello> hello = new CompletableFuture<>();
    private final Object deathLock = new Object();
    private volatile String deathReason;
    private volatile boolean closing;
    /** When the simulator last wrote a line; the watchdog pings it when it has been quiet while actions run. */
    private volatile long lastHeard = System.nanoTime();
    private final ScheduledExecutorService watchdog =
            Executors.newSingleThreadScheduledExecutor(Thread.ofPlatform().daemon().name("sim-watchdog").factory());
    private CompletableFuture<JsonNode> ping = CompletableFuture.completedFuture(null);

    private SimWorld(SimOptions options, SimProcess process) {
        this.options = options;
        this.process = process;
    }

    /** Starts the simulator and waits for its {@code hello}. */
    public static SimWorld start(SimOptions options) {
        Objects.requireNonNull(options, "options");
        SimProcess process = SimProcess.launch(options);
        SimWorld world = new SimWorld(options, process);
        world.startThreads();
        try {
            SimEvent.Hello h = world.hello.get(options.requestTimeout().toMillis() + 20_000, TimeUnit.MILLISECONDS);
            LOG.info("Simulator {} started (pid {}, seed {}, mode {})", h.protocol(), process.pid(), h.seed(), h.mode());
            return world;
        } catch (ExecutionException e) {
            if (!(e.getCause() instanceof SimulatorExitedException)) { // alive, but not speaking the protocol
                world.process.killTree();
                world.close();
                throw new SimulatorException("The simulator did not start: " + e.getCause().getMessage());
            }
            world.close();
            throw new SimulatorExitedException("The simulator did not start: " + e.getCause().getMessage());
        } catch (TimeoutException e) {
            world.close();
            throw new SimulatorException("The simulator sent no hello within "
                    + (options.requestTimeout().toSeconds() + 20) + " s.");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            world.close();
            throw new SimulatorException("Interrupted while starting the simulator.", e);
        }
    }

    private void startThreads() {
        process.follow(this::heard, this::die, this::alive, () -> closing);
        if (!options.manual()) { // in manual mode nothing runs between steps, and a long step answers late
            long period = Math.max(50, options.requestTimeout().toMillis() / 4);
            try {
                watchdog.scheduleWithFixedDelay(this::watch, period, period, TimeUnit.MILLISECONDS);
            } catch (RejectedExecutionException e) {
                LOG.debug("The simulator died before its watchdog started: {}", deathReason);
            }
        }
    }

    /** The simulator's first line: protocol, seed, mode, robots and their actions. */
    public SimEvent.Hello hello() {
        return hello.join();
    }

    public SimOptions options() {
        return options;
    }

    /** The operating-system id of the simulator process (tests kill it with it). */
    public long pid() {
        return process.pid();
    }

    public boolean alive() {
        return deathReason == null;
    }

    /** How the simulator died, once it has. */
    public Optional<String> deathReason() {
        return Optional.ofNullable(deathReason);
    }

    /** Adds a listener for every event, called in order on the event thread; it must not block on this world. */
    public AutoCloseable addListener(Consumer<SimEvent> listener) {
        Objects.requireNonNull(listener, "listener");
        return events.addListener(listener);
    }

    /**
     * Sends a request; the future completes with the ack's result, or fails with {@link SimRequestRejectedException},
     * {@link SimulatorExitedException} or a {@link TimeoutException}.
     *
     * @throws IllegalArgumentException when the request's line would be longer than {@link SimCodec#MAX_LINE}
     */
    public CompletableFuture<Optional<JsonNode>> request(SimRequest request) {
        Objects.requireNonNull(request, "request");
        if (request instanceof SimRequest.Command c) {
            throw new IllegalArgumentException("Send command '" + c.action() + "' with command(...), which follows it.");
        }
        failIfDead();
        String id = nextId();
        String line = codec.encode(id, request); // first: a request too long to send leaves nothing waiting
        CompletableFuture<Optional<JsonNode>> ack = new CompletableFuture<>();
        pending.put(id, ack);
        Duration timeout = request instanceof SimRequest.Step s
                ? options.requestTimeout().plusMillis((long) (s.seconds() * 1000)) : options.requestTimeout();
        ack.orTimeout(timeout.toMillis(), TimeUnit.MILLISECONDS).whenComplete((r, e) -> {
            pending.remove(id);
            if (e instanceof TimeoutException) {
                stopIfHung(timeout);
            }
        });
        try {
            send(line);
        } catch (SimulatorExitedException e) {
            pending.remove(id);
            throw e;
        }
        return ack;
    }

    /** Sends a request and waits for its ack's result. */
    public Optional<JsonNode> call(SimRequest request) {
        return await(request(request));
    }

    /** The whole world state now (robots, users, cups, obstacles). */
    public JsonNode query() {
        return await(queryAsync());
    }

    private CompletableFuture<JsonNode> queryAsync() {
        failIfDead();
        String id = nextId();
        String line = codec.encode(id, new SimRequest.Query());
        CompletableFuture<JsonNode> state = new CompletableFuture<>();
        queries.put(id, state);
        state.orTimeout(options.requestTimeout().toMillis(), TimeUnit.MILLISECONDS).whenComplete((r, e) -> {
            queries.remove(id);
            if (e instanceof TimeoutException) {
                stopIfHung(options.requestTimeout());
            }
        });
        try {
            send(line);
        } catch (SimulatorExitedException e) {
            queries.remove(id);
            throw e;
        }
        return state;
    }

    /** Real time: while actions run and the simulator has been quiet for half the request timeout, ping it. */
    private void watch() {
        long quiet = System.nanoTime() - lastHeard;
        if (!alive() || actions.isEmpty() || quiet < options.requestTimeout().toNanos() / 2 || !ping.isDone()) {
            return;
        }
        try {
            ping = queryAsync();
        } catch (SimulatorExitedException e) {
            watchdog.shutdown();
        }
    }

    /**
     * Real time: a simulator that answers no request within the timeout is hung (it answers between physics steps,
     * within milliseconds); it is stopped, and everything in flight fails saying so.
     */
    private void stopIfHung(Duration waited) {
        if (options.manual() || closing || !alive() || System.nanoTime() - lastHeard < waited.toNanos()) {
            return; // a simulator that wrote a line within the timeout is slow (or this JVM was paused), not hung
        }
        String time = waited.toMillis() % 1000 == 0 ? waited.toSeconds() + " s" : waited.toMillis() + " ms";
        die("simulator did not answer within " + time + " and was stopped");
        process.kill();
    }

    /** Manual mode: advances the world by {@code seconds} (stopping early when idle, if asked) and waits. */
    public void step(double seconds, boolean untilIdle) {
        call(new SimRequest.Step(seconds, untilIdle));
    }

    /**
     * Sends a command and follows it: {@code observer} gets every update on the event thread.
     *
     * @throws IllegalArgumentException when the command's line would be longer than {@link SimCodec#MAX_LINE}
     */
    public SimAction command(SimRequest.Command command, Consumer<ActionUpdate> observer) {
        Objects.requireNonNull(command, "command");
        failIfDead();
        String id = nextId();
        String line = codec.encode(id, command); // first: a command too long to send leaves nothing waiting
        SimAction action = new SimAction(id, command, observer);
        actions.put(id, action);
        action.outcome().whenComplete((r, e) -> actions.remove(id));
        CompletableFuture<Optional<JsonNode>> ack = new CompletableFuture<>();
        pending.put(id, ack);
        ack.orTimeout(options.requestTimeout().toMillis(), TimeUnit.MILLISECONDS).whenComplete((r, e) -> {
            pending.remove(id);
            if (e instanceof TimeoutException) {
                stopIfHung(options.requestTimeout());
            }
            if (e != null && !(e instanceof SimulatorExitedException) && alive()) { // die() reports a death, with its reason
                String reason = e instanceof TimeoutException
                        ? "no answer from the simulator within " + options.requestTimeout().toSeconds() + " s"
                        : e.getMessage();
                events.post(() -> SimEventThread.deliverSafely(action, new ActionUpdate.Failed(Double.NaN, reason)));
            }
        });
        try {
            send(line);
        } catch (SimulatorExitedException e) {
            actions.remove(id);
            pending.remove(id);
            throw e;
        }
        return action;
    }

    /** Sends a command without an observer. */
    public SimAction command(SimRequest.Command command) {
        return command(command, u -> { });
    }

    private String nextId() {
        return "j" + ids.incrementAndGet();
    }

    /** Queues a request line; the writer thread sends it, and a broken pipe kills the world there. */
    private void send(String line) {
        failIfDead();
        process.send(line);
    }

    private void failIfDead() {
        String reason = deathReason;
        if (reason != null) {
            throw new SimulatorExitedException("The simulator is not running: " + reason + ".");
        }
    }

    private static <T> T await(CompletableFuture<T> future) {
        try {
            return future.get();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            switch (cause) { // a fresh exception, so the stack trace shows the caller
                case SimulatorExitedException x -> throw new SimulatorExitedException(x.getMessage());
                case SimRequestRejectedException r -> throw new SimRequestRejectedException(r.getMessage(), r.field());
                case SimulatorException x -> throw new SimulatorException(x.getMessage(), x);
                default -> { }
            }
            if (cause instanceof TimeoutException) {
                throw new SimulatorException("The simulator did not answer in time.", cause);
            }
            throw new SimulatorException("A simulator request failed: " + cause, cause);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SimulatorException("Interrupted while waiting for the simulator.", e);
        }
    }

    /** On the reader thread: a line from the simulator's stdout. */
    private void heard(String line) {
        lastHeard = System.nanoTime();
        LOG.trace("<- {}", line);
        handleLine(line);
    }

    private void handleLine(String line) {
        SimEvent event;
        try {
            event = codec.decode(line);
        } catch (SimProtocolException e) {
            if (!hello.isDone()) { // the first line must be the hello: no use waiting for another
                hello.completeExceptionally(new SimulatorException("The simulator's first line is not a valid hello: "
                        + e.getMessage()));
            }
            LOG.warn("{}", e.getMessage());
            return;
        }
        if (!hello.isDone() && !(event instanceof SimEvent.Hello)) {
            hello.completeExceptionally(new SimulatorException("The simulator's first line is not a valid hello but a "
                    + event.getClass().getSimpleName() + " event: " + SimCodec.bad(line, "expected a hello").getMessage()));
        }
        switch (event) {
            case SimEvent.Hello h when !h.protocol().equals(PROTOCOL) -> hello.completeExceptionally(new SimulatorException(
                    "The simulator speaks " + h.protocol() + "; this platform speaks " + PROTOCOL + "."));
            case SimEvent.Hello h -> hello.complete(h);
            case SimEvent.Ack a -> {
                if (!queries.containsKey(a.id())) {
                    complete(a.id(), a.result());
                }
            }
            case SimEvent.Error err -> err.id().ifPresentOrElse(id -> reject(id, err),
                    () -> LOG.warn("Simulator error without a request id: {}", err.message()));
            case SimEvent.State s -> s.id().map(queries::get).ifPresent(q -> q.complete(s.world()));
            default -> { }
        }
        events.post(() -> events.dispatch(event));
    }

    private void complete(String id, Optional<JsonNode> result) {
        CompletableFuture<Optional<JsonNode>> f = pending.get(id);
        if (f != null) {
            f.complete(result);
        }
    }

    private void reject(String id, SimEvent.Error err) {
        SimRequestRejectedException e = new SimRequestRejectedException(err.message(), err.field());
        CompletableFuture<Optional<JsonNode>> f = pending.get(id);
        if (f != null) {
            f.completeExceptionally(e);
        }
        CompletableFuture<JsonNode> q = queries.get(id);
        if (q != null) {
            q.completeExceptionally(e);
        }
    }

    /** Marks the world dead once: fails everything in flight and tells the listeners. */
    private void die(String reason) {
        synchronized (deathLock) {
            if (deathReason != null) {
                return;
            }
            deathReason = reason;
        }
        if (closing) {
            LOG.info("Simulator stopped: {}", reason);
        } else {
            LOG.error("Simulator died: {}", reason);
        }
        SimulatorExitedException dead = new SimulatorExitedException("The simulator is not running: " + reason + ".");
        process.discardQueued();
        watchdog.shutdownNow();
        hello.completeExceptionally(dead);
        pending.values().forEach(f -> f.completeExceptionally(dead));
        queries.values().forEach(f -> f.completeExceptionally(dead));
        events.post(() -> {
            List.copyOf(actions.values())
                    .forEach(a -> SimEventThread.deliverSafely(a, new ActionUpdate.Failed(Double.NaN, reason)));
            events.dispatch(new SimEvent.Exited(reason));
        });
        events.shutdown();
    }

    /** Asks the simulator to shut down, waits a little, then stops it by force; idempotent. */
    @Override public void close() {
        closing = true;
        if (alive()) {
            try {
                request(new SimRequest.Shutdown()).get(2, TimeUnit.SECONDS);
            } catch (ExecutionException | TimeoutException | SimulatorException e) {
                LOG.debug("Shutdown request: {}", e.toString());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        process.awaitExit();
        try {
            process.joinReader(Duration.ofSeconds(3));
            events.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
