package org.kicnp.core;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.kicnp.core.Frames.cls;
import static org.kicnp.core.Frames.root;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The knowledge base remembers what validation learnt of its classes between batches that add or change instances
 * only; these tests change classes in between and check that instances are then judged by the classes as they are.
 */
class KnowledgeBaseClassCacheTest {

    @Test
    void add_afterTheClassChangedASlotType_checksTheInstanceAgainstTheNewType() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.add(Frame.classFrame("Robot").slot(Slot.builder("speed", DataType.FLOAT).build()).build());
        kb.add(Frame.instance("r1", "Robot").slot(Slot.ofValue("speed", DataType.FLOAT, Value.of(1.5))).build());

        kb.replace(Frame.classFrame("Robot").slot(Slot.builder("speed", DataType.STRING).build()).build());

        assertThatThrownBy(() -> kb.add(Frame.instance("r2", "Robot")
                .slot(Slot.ofValue("speed", DataType.FLOAT, Value.of(2.0))).build()))
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Slot 'speed' of frame 'r2' is TYPE_FLOAT but 'Robot' declares it TYPE_STR.");
    }

    @Test
    void add_afterAClassMovedInTheHierarchy_checksValuesAgainstItsNewAncestors() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(List.of(new Change.Add(root("Pet")), new Change.Add(root("Animal")), new Change.Add(cls("Dog", "Pet")),
                new Change.Add(Frame.classFrame("Owner")
                        .slot(Slot.builder("pet", DataType.INSTANCE).argument("Pet").build()).build())));
        kb.add(Frame.instance("rex", "Dog").build());
        kb.add(owner("o1", "rex"));

        kb.replace(cls("Dog", "Animal"));

        assertThatThrownBy(() -> kb.add(owner("o2", "rex")))
                .isInstanceOf(BatchRejectedException.class)
                .hasMessage("Slot 'pet' of frame 'o2' must hold an instance of 'Pet', but 'rex' is not one.");
        assertThat(kb.instancesOf("Pet")).isEmpty();
        assertThat(kb.instancesOf("Animal")).extracting(Frame::name).containsExactly("rex");
    }

    @Test
    void add_afterARejectedInstance_stillAcceptsAValidOne() {
        KnowledgeBase kb = KnowledgeBase.create();
        kb.apply(List.of(new Change.Add(root("Pet")), new Change.Add(cls("Dog", "Pet")), new Change.Add(root("Toy")),
                new Change.Add(Frame.classFrame("Owner")
                        .slot(Slot.builder("pet", DataType.INSTANCE).argument("Pet").build()).build())));
        kb.apply(List.of(new Change.Add(Frame.instance("rex", "Dog").build()),
                new Change.Add(Frame.instance("ball", "Toy").build())));

        assertThatThrownBy(() -> kb.add(owner("o1", "ball"))).isInstanceOf(BatchRejectedException.class);
        kb.add(owner("o2", "rex"));

        assertThat(kb.instancesOf("Owner")).extracting(Frame::name).containsExactly("o2");
        assertThat(kb.linksInto("rex")).isEmpty();
    }

    private static Frame owner(String name, String pet) {
        return Frame.instance(name, "Owner").slot(Slot.ofValue("pet", DataType.INSTANCE, Value.ref(pet))).build();
    }
}
