package org.kicnp.core.xml;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.function.Consumer;
import org.kicnp.core.KnowledgeException;

/**
 * Hands frames read on the calling thread to a consumer on a second thread, in order and in batches, so that
 * tokenizing XML and mapping frames overlap on a large load. The queue is bounded, so the reader never runs more than
 * a few thousand frames ahead. The consumer's state must only be read after {@link #finish()}, which joins.
 */
final class MappingPipeline implements Consumer<FrameElement> {
    private static final int BATCH = 256;
    private static final List<FrameElement> END = new ArrayList<>(0);

    private final ArrayBlockingQueue<List<FrameElement>> queue = new ArrayBlockingQueue<>(32);
    private final Thread worker;
    private List<FrameElement> batch = new ArrayList<>(BATCH);
    private volatile Throwable failure;
    private boolean finished;

    MappingPipeline(Consumer<FrameElement> target) {
        worker = Thread.ofPlatform().name("kicnp-xml-mapper").daemon(true).start(() -> run(target));
    }

    private void run(Consumer<FrameElement> target) {
        try {
            while (true) {
                List<FrameElement> b = queue.take();
                if (b == END) {
                    return;
                }
                if (failure == null) {
                    try {
                        b.forEach(target);
                    } catch (RuntimeException | Error e) {
                        // Keep draining so the reader never blocks on a full queue; finish() rethrows.
                        failure = e;
                    }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override public void accept(FrameElement e) {
        batch.add(e);
        if (batch.size() == BATCH) {
            put(batch);
            batch = new ArrayList<>(BATCH);
        }
    }

    /** Hands over what is left, waits until every frame is consumed, and rethrows what the consumer threw. */
    void finish() {
        if (finished) {
            return;
        }
        finished = true;
        if (!batch.isEmpty()) {
            put(batch);
        }
        put(END);
        try {
            worker.join();
        } catch (InterruptedException e) {
            worker.interrupt();
            Thread.currentThread().interrupt();
            throw new KnowledgeException("Loading knowledge files was interrupted.", e);
        }
        Throwable t = failure;
        if (t instanceof RuntimeException re) {
            throw re;
        }
        if (t instanceof Error err) {
            throw err;
        }
    }

    /** Stops the worker without waiting, after the reader failed. */
    void abandon() {
        if (!finished) {
            finished = true;
            worker.interrupt();
        }
    }

    private void put(List<FrameElement> b) {
        try {
            queue.put(b);
        } catch (InterruptedException e) {
            worker.interrupt();
            Thread.currentThread().interrupt();
            throw new KnowledgeException("Loading knowledge files was interrupted.", e);
        }
    }
}
