package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.Frames.cls;
import static org.kicnp.core.Frames.figure1;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * {@link KnowledgeBase#hold}: one thread's burst of changes without a lock per change. What it must keep: every
 * change validated and delivered in commit order, other threads kept out until the hold ends and let in after it,
 * and a hold that cannot be taken safely (inside a delivery) doing nothing.
 */
class KnowledgeBaseHoldTest {
    /** Long enough for a thread that is not blocked to have finished a look-up many times over. */
    private static final long BLOCKED_MS = 300;
    /** Changes each writer makes in the test of holds and plain changes from four threads at once. */
    private static final int PER_WRITER = 2_000;
    /** Threads of their own for the other threads' calls: one left blocked must not hold up the next. */
    private final ExecutorService pool = Executors.newCachedThreadPool();

    @AfterEach
    void stopPool() {
        pool.shutdownNow();
    }

    private static Frame user(String name) {
        return Frame.instance(name, "NewUser").provenance(Provenance.RUNTIME).build();
    }

    @Test
    void holdersChanges_reachListenersAtOnceInCommitOrder_andAListenersChangeAfterTheBatchItHears() {
        KnowledgeBase kb = figure1();
        List<String> heard = new ArrayList<>();
        kb.addListener(cs -> {
            cs.events().forEach(e -> heard.add("1:" + e.name()));
            if (cs.events().stream().anyMatch(e -> e.name().equals("ken"))) {
                kb.add(Frame.instance("greeting1", "Speech").provenance(Provenance.RUNTIME).build());
                heard.add("after nested add");
            }
        });
        kb.addListener(cs -> cs.events().forEach(e -> heard.add("2:" + e.name())));
        try (KnowledgeBase.Hold h = kb.hold()) {
            kb.add(user("ken"));
            assertThat(heard).as("heard before the add returned, every listener, the nested change last")
                    .containsExactly("1:ken", "after nested add", "2:ken", "1:greeting1", "2:greeting1");
            kb.add(user("ana"));
        }
        assertThat(heard).endsWith("1:ana", "2:ana");
        assertThat(kb.contains("greeting1")).isTrue();
    }

    @Test
    void otherThreads_waitForTheHoldToEnd_thenTheirChangesFollowTheHolders() throws Exception {
        KnowledgeBase kb = figure1();
        long start = kb.version();
        List<Long> heard = Collections.synchronizedList(new ArrayList<>());
        kb.addListener(cs -> heard.add(cs.version()));
        CompletableFuture<Boolean> read;
        CompletableFuture<ChangeSet> write;
        try (KnowledgeBase.Hold h = kb.hold()) {
            kb.add(user("u1"));
            read = CompletableFuture.supplyAsync(() -> kb.contains("u1"), pool);
            write = CompletableFuture.supplyAsync(() -> kb.add(user("other")), pool);
            Thread.sleep(BLOCKED_MS);
            assertThat(read).as("a read by another thread waits").isNotDone();
            assertThat(write).as("a change by another thread waits").isNotDone();
            kb.add(user("u2"));
            assertThat(kb.contains("u2")).as("the holder reads its own changes").isTrue();
        }
        assertThat(read.get(10, TimeUnit.SECONDS)).isTrue();
        assertThat(write.get(10, TimeUnit.SECONDS).version()).isEqualTo(start + 3);
        assertThat(heard).containsExactly(start + 1, start + 2, start + 3);
    }

    @Test
    void aRejectedChangeInAHold_leavesTheBaseAsItWas_andTheHoldGoesOn() throws Exception {
        KnowledgeBase kb = figure1();
        try (KnowledgeBase.Hold h = kb.hold()) {
            kb.add(user("u1"));
            long v = kb.version();
            assertThatThrownBy(() -> kb.add(Frame.instance("u2", "NoSuchClass").build()))
                    .isInstanceOf(BatchRejectedException.class).hasMessageContaining("NoSuchClass");
            assertThat(kb.version()).isEqualTo(v);
            assertThat(kb.contains("u2")).isFalse();
            kb.add(user("u3"));
        }
        assertThat(kb.contains("u3")).isTrue();
        assertThat(CompletableFuture.supplyAsync(() -> kb.add(user("u4")), pool).get(10, TimeUnit.SECONDS).events())
                .hasSize(1);
    }

    @Test
    void aHoldTakenInsideADelivery_doesNothing_soTheBatchBeingHeardReachesEveryListenerFirst() throws Exception {
        KnowledgeBase kb = figure1();
        List<String> heard = new ArrayList<>();
        boolean[] otherThreadRead = {false};
        kb.addListener(cs -> {
            cs.events().forEach(e -> heard.add("1:" + e.name()));
            if (cs.events().stream().anyMatch(e -> e.name().equals("ken"))) {
                try (KnowledgeBase.Hold h = kb.hold()) {
                    kb.add(user("nested"));
                    heard.add("after nested add");
                    // not held: another thread reads while this listener runs
                    otherThreadRead[0] = CompletableFuture.supplyAsync(() -> kb.contains("nested"), pool)
                            .get(10, TimeUnit.SECONDS);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }
        });
        kb.addListener(cs -> cs.events().forEach(e -> heard.add("2:" + e.name())));
        kb.add(user("ken"));
        assertThat(heard).containsExactly("1:ken", "after nested add", "2:ken", "1:nested", "2:nested");
        assertThat(otherThreadRead[0]).isTrue();
    }

    @Test
    void closingTwice_orFromAnotherThread_doesNothing_andAHoldWithinAHoldIsTheSameHold() throws Exception {
        KnowledgeBase kb = figure1();
        KnowledgeBase.Hold first = kb.hold();
        KnowledgeBase.Hold inner = kb.hold();
        inner.close();
        assertThat(CompletableFuture.supplyAsync(() -> kb.contains("Speech"), pool).completeOnTimeout(null, BLOCKED_MS,
                TimeUnit.MILLISECONDS).get()).as("still held after the inner hold's close").isNull();
        CompletableFuture.runAsync(first::close, pool).get(10, TimeUnit.SECONDS);
        assertThat(CompletableFuture.supplyAsync(() -> kb.contains("Speech"), pool).completeOnTimeout(null, BLOCKED_MS,
                TimeUnit.MILLISECONDS).get()).as("still held after a close from another thread").isNull();
        first.close();
        assertThat(CompletableFuture.supplyAsync(() -> kb.contains("Speech"), pool).get(10, TimeUnit.SECONDS)).isTrue();

        KnowledgeBase.Hold second = kb.hold();
        first.close(); // closed already: must not end the second hold
        assertThat(CompletableFuture.supplyAsync(() -> kb.contains("Speech"), pool).completeOnTimeout(null, BLOCKED_MS,
                TimeUnit.MILLISECONDS).get()).as("a second close of the first hold left the second one").isNull();
        second.close();
        assertThat(CompletableFuture.supplyAsync(() -> kb.add(user("after")), pool).get(10, TimeUnit.SECONDS).events())
                .hasSize(1);
    }

    @Test
    void aHoldClosedInsideAListener_endsWhenThatDeliveryIsOver() throws Exception {
        KnowledgeBase kb = figure1();
        KnowledgeBase.Hold[] hold = {null};
        List<String> heard = new ArrayList<>();
        kb.addListener(cs -> {
            cs.events().forEach(e -> heard.add("1:" + e.name()));
            if (cs.events().stream().anyMatch(e -> e.name().equals("ken"))) {
                hold[0].close();
                kb.add(user("nested")); // still this thread's hold: delivered after ken
            }
        });
        kb.addListener(cs -> cs.events().forEach(e -> heard.add("2:" + e.name())));
        hold[0] = kb.hold();
        kb.add(user("ken"));
        assertThat(heard).containsExactly("1:ken", "2:ken", "1:nested", "2:nested");
        assertThat(CompletableFuture.supplyAsync(() -> kb.add(user("other")), pool).get(10, TimeUnit.SECONDS).events())
                .as("the hold ended once the delivery was over").hasSize(1);
    }

    @Test
    void listenersHearEveryVersionOnceInCommitOrder_oneAtATime_whileHoldsAndPlainChangesInterleave() throws Exception {
        KnowledgeBase kb = figure1();
        DeliveryProbe probe = DeliveryProbe.on(kb);
        DeliveryProbe.together(4, id -> {
            int i = 0;
            while (i < PER_WRITER) {
                if (id % 2 == 0) { // bursts of up to 10 changes in a hold
                    try (KnowledgeBase.Hold h = kb.hold()) {
                        for (int k = 0; k < 10 && i < PER_WRITER; k++, i++) {
                            kb.add(i % 5 == 0 ? cls("C" + id + "_" + i, "Speech") : user("u" + id + "_" + i));
                        }
                    }
                } else {
                    kb.add(i % 5 == 0 ? cls("C" + id + "_" + i, "Speech") : user("u" + id + "_" + i));
                    i++;
                }
            }
        });
        probe.assertHeardInOrder(4 * PER_WRITER);
        assertThat(kb.countInstancesOf("NewUser")).isEqualTo(4 * PER_WRITER * 4 / 5);
    }
}
