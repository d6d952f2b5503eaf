package org.kicnp.script;

import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.atomic.AtomicInteger;

import org.graalvm.polyglot.Context;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Idle sandboxed contexts waiting for a run. A context taken with {@link #acquire()} belongs to the calling
 * thread until it is handed back with {@link #release} or {@link #discard}, so no context is ever used by two
 * threads at once. Under load new contexts are created; at most {@code maxIdle} are kept.
 */
final class ContextPool implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ContextPool.class);

    private final Sandbox sandbox;
    private final int maxIdle;
    private final ConcurrentLinkedDeque<Context> idle = new ConcurrentLinkedDeque<>();
    private final AtomicInteger idleCount = new AtomicInteger();
    private final AtomicInteger created = new AtomicInteger();
    private volatile boolean closed;

    ContextPool(Sandbox sandbox, int maxIdle) {
        this.sandbox = sandbox;
        this.maxIdle = maxIdle;
    }

    /** An idle context, or a new one when none is idle. The caller owns it until it gives it back. */
    Context acquire() {
        Context context = idle.pollFirst();
        if (context != null) {
            idleCount.decrementAndGet();
            return context;
        }
        created.incrementAndGet();
        return sandbox.newContext();
    }

    /** Gives back a healthy context for reuse, or closes it when enough are idle. */
    void release(Context context) {
        if (!closed && idleCount.incrementAndGet() <= maxIdle) {
            idle.offerFirst(context);
            if (closed && idle.remove(context)) {
                discard(context);
            }
            return;
        }
        idleCount.decrementAndGet();
        discard(context);
    }

    /** Closes a context that must not be reused: it was stopped, exhausted its limits or is in doubt. */
    void discard(Context context) {
        try {
            context.close(true);
        } catch (RuntimeException e) {
            LOG.debug("Closing a discarded script context failed; it is dropped anyway.", e);
        }
    }

    /** How many contexts this pool has created, for tests and diagnostics. */
    int created() {
        return created.get();
    }

    @Override public void close() {
        closed = true;
        for (Context context = idle.pollFirst(); context != null; context = idle.pollFirst()) {
            discard(context);
        }
    }
}
