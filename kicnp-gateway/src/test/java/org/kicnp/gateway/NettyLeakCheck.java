package org.kicnp.gateway;

import static org.junit.jupiter.api.Assertions.fail;

import io.netty.buffer.AbstractByteBuf;
import io.netty.buffer.ByteBufAllocator;
import io.netty.util.ResourceLeakDetector;
import io.netty.util.ResourceLeakDetectorFactory;
import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Fails a test class after which a Netty buffer was found leaked: collected by the garbage collector without being
 * released, so its memory (pooled, often direct) never went back to the allocator. Registered for every test class of
 * this module (META-INF/services, autodetection on in its surefire configuration), it makes Netty track every buffer
 * with where it was touched ({@link ResourceLeakDetector.Level#PARANOID}; the platform keeps Netty's default, which
 * samples one buffer in 128) and listens to what Netty's buffer leak detectors report. Netty finds a leak only when a
 * buffer it tracks has been collected and a later buffer is tracked, so after each class it asks for collections and
 * allocates until what was collected has been looked at. A leak seen then may come from an earlier class whose buffers
 * the collector had not yet reached; the records name where the buffer was made and last touched. Netty reports a leak
 * once per distinct record (the same leak again from the same places is not reported again).
 */
public final class NettyLeakCheck implements AfterAllCallback {

    private static final Queue<String> LEAKS = new ConcurrentLinkedQueue<>();

    static {
        ResourceLeakDetector.setLevel(ResourceLeakDetector.Level.PARANOID); // read by every track(), from now on
        // Listen to the detectors made from now on (through the factory) and to AbstractByteBuf's, the allocators',
        // which is made once per JVM and may already exist when this class is loaded (as when a test loads it before
        // JUnit registers it: seen in a fresh clone's run while the registration was not on).
        ResourceLeakDetectorFactory.setResourceLeakDetectorFactory(new ResourceLeakDetectorFactory() {
            @Override
            public <T> ResourceLeakDetector<T> newResourceLeakDetector(Class<T> resource, int samplingInterval,
                    long maxActive) {
                return listenedTo(new ResourceLeakDetector<>(resource, samplingInterval));
            }
        });
        try {
            Field f = AbstractByteBuf.class.getDeclaredField("leakDetector");
            f.setAccessible(true);
            listenedTo((ResourceLeakDetector<?>) f.get(null));
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new IllegalStateException("NettyLeakCheck cannot listen to Netty's buffer leak detector "
                    + "(AbstractByteBuf.leakDetector), so it would miss leaks: " + e, e);
        }
    }

    private static <T> ResourceLeakDetector<T> listenedTo(ResourceLeakDetector<T> d) {
        d.setLeakListener((type, records) -> LEAKS.add(type + " leaked:" + records));
        return d;
    }

    @Override
    public void afterAll(ExtensionContext context) throws InterruptedException {
        List<String> leaks = collectLeaks();
        if (!leaks.isEmpty()) {
            fail(leaks.size() + " Netty buffer(s) found leaked after " + context.getDisplayName() + " (or a class "
                    + "before it):\n" + String.join("\n", leaks));
        }
    }

    /** Collects garbage, lets Netty look at what it collected, and returns (and forgets) the leaks reported. */
    static List<String> collectLeaks() throws InterruptedException {
        return collectLeaks(0, 5);
    }

    /**
     * As {@link #collectLeaks()}, going on for up to {@code maxRounds} rounds of collecting and looking until at
     * least {@code atLeast} leaks were reported: a collection does not always reach every buffer that is garbage.
     */
    static List<String> collectLeaks(int atLeast, int maxRounds) throws InterruptedException {
        for (int i = 0; i < maxRounds && (i < 5 || LEAKS.size() < atLeast); i++) {
            System.gc();
            Thread.sleep(20); // the collected buffers' references are queued by the reference handler thread
            ByteBufAllocator.DEFAULT.buffer(1).release(); // each tracked buffer makes Netty poll that queue
        }
        List<String> leaks = new ArrayList<>();
        for (String leak; (leak = LEAKS.poll()) != null; ) {
            leaks.add(leak);
        }
        return leaks;
    }
}
