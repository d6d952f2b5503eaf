package org.kicnp.inference;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.kicnp.core.Frame;

class MatchNetworkTest {

    private static Fixture usersAndOrders(int users) {
        Fixture f = new Fixture();
        f.cls("User", null).cls("Order", null);
        f.kb.add(Frame.classFrame("Deliver").slot(Fixture.inst("mUser", "User"))
                .slot(Fixture.inst("mOrder", "Order", ".who == mUser.name")).build());
        for (int i = 0; i < users; i++) {
            f.assertFact("u" + i, "User", "name", "n" + i);
        }
        return f;
    }

    /** A network reading the knowledge base directly, with the Deliver rule installed. */
    private static MatchNetwork deliveries(Fixture f) {
        MatchNetwork network = new MatchNetwork(f.kb, new Conditions((frame, slot) ->
                f.kb.contains(frame) ? f.kb.value(frame, slot) : Optional.empty()));
        network.addRule(new RuleCompiler(f.kb).compile("Deliver").orElseThrow());
        return network;
    }

    @Test
    void insert_whenJoinedByEquality_readsOnlyTheIndexedPartnerNotEveryInstance() {
        Fixture f = usersAndOrders(2_000);
        AtomicInteger reads = new AtomicInteger();
        Conditions counting = new Conditions((frame, slot) -> {
            reads.incrementAndGet();
            return f.kb.contains(frame) ? f.kb.value(frame, slot) : Optional.empty();
        });
        MatchNetwork network = new MatchNetwork(f.kb, counting);
        Rule rule = new RuleCompiler(f.kb).compile("Deliver").orElseThrow();
        assertThat(network.addRule(rule)).isEmpty();

        f.assertFact("o1", "Order", "who", "n1234");
        reads.set(0);
        var matches = network.insert("o1", "Order");
        assertThat(matches).singleElement().satisfies(m -> assertThat(m.binding()).containsEntry("mUser", "u1234"));
        assertThat(reads.get()).isLessThan(10);

        f.assertFact("uX", "User", "name", "n1234");
        reads.set(0);
        assertThat(network.insert("uX", "User")).singleElement()
                .satisfies(m -> assertThat(m.binding()).containsEntry("mOrder", "o1"));
        assertThat(reads.get()).isLessThan(10);
    }

    /** Room made for a large batch (the index rebuilt at its new size) keeps what the memory held. */
    @Test
    void expect_aLargeBatch_keepsTheMembersAndTheirIndexKeys() {
        Fixture f = usersAndOrders(10);
        MatchNetwork network = deliveries(f);

        network.expect("User", 200); // more than twice what the users' memory holds: it grows before the batch
        network.expect("Order", 200);
        for (int i = 10; i < 210; i++) {
            f.assertFact("u" + i, "User", "name", "n" + i);
            assertThat(network.insert("u" + i, "User")).isEmpty();
        }

        f.assertFact("o1", "Order", "who", "n5");
        assertThat(network.insert("o1", "Order")).singleElement() // a user from before the batch
                .satisfies(m -> assertThat(m.binding()).containsEntry("mUser", "u5"));
        f.assertFact("o2", "Order", "who", "n150");
        assertThat(network.insert("o2", "Order")).singleElement()
                .satisfies(m -> assertThat(m.binding()).containsEntry("mUser", "u150"));
        assertThat(network.candidates("Deliver", "mUser")).hasSize(210).startsWith("u0", "u1");
    }

    @Test
    void retract_thenInsert_keepsIndexesConsistent() {
        Fixture f = usersAndOrders(3);
        MatchNetwork network = deliveries(f);
        f.assertFact("o1", "Order", "who", "n2");
        assertThat(network.insert("o1", "Order")).hasSize(1);
        network.retract("u2");
        assertThat(network.rematch("Deliver", "mOrder", "o1")).isEmpty();
        assertThat(network.insert("u2", "User")).hasSize(1);
        assertThat(network.candidates("Deliver", "mUser")).containsExactly("u0", "u1", "u2");
    }
}
