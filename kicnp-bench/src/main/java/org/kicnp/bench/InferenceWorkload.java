package org.kicnp.bench;

import java.util.ArrayList;
import java.util.List;
import org.kicnp.core.Change;
import org.kicnp.core.ConditionParser;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * The one generated workload of {@code ./kicnp bench inference}, written out for both engines from the same
 * description, so they do the same work.
 *
 * <p>IS-A hierarchy: {@code Stimulus} (slot {@code key}) with kinds {@code StimA}, {@code StimB}, {@code StimC};
 * {@code Derived} with the behavior frames below it. Three levels of behavior frames, each with two instance slots and
 * one condition joining slot values:
 * <pre>
 *   Pair   (priority 1): mA: StimA, mB: StimB  .key == mA.key
 *   Triple (priority 2): mP: Pair,  mC: StimC  .key == mP.mA.key
 *   Alert  (priority 3): mT: Triple, mA: StimA .key == mT.mP.mA.key
 * </pre>
 * Stimulus {@code i} has key {@code i / 4} and is a StimA, StimA, StimB, StimC for {@code i % 4} = 0, 1, 2, 3, so a
 * full key group of 2 A, 1 B, 1 C gives 2 Pairs, 2 Triples and 2 × 2 Alerts: 8 firings per 4 stimuli
 * ({@link #expectedFirings()} counts partial groups too). Priorities are explicit and identical on both sides: Drools
 * does not prefer recent facts among rules of equal salience, K-ICNP does, so leaving them equal would let the two
 * engines take different paths to the same end.
 */
record InferenceWorkload(int n) {
    /** Stimuli per key. */
    static final int GROUP = 4;
    static final String DRL_PACKAGE = "org.kicnp.bench.drools";

    InferenceWorkload {
        if (n < 1) {
            throw new IllegalArgumentException("The workload needs at least one stimulus, not " + n + ".");
        }
    }

    /** The class of stimulus {@code i}. */
    static String stimulusClass(int i) {
        return switch (i % GROUP) {
            case 0, 1 -> "StimA";
            case 2 -> "StimB";
            default -> "StimC";
        };
    }

    static int key(int i) {
        return i / GROUP;
    }

    /** The explicit priority (K-ICNP) and salience (Drools) of each level's behavior frame. */
    static int priority(String frame) {
        return switch (frame) {
            case "Pair" -> 1;
            case "Triple" -> 2;
            case "Alert" -> 3;
            default -> throw new IllegalArgumentException("No behavior frame '" + frame + "' in the workload.");
        };
    }

    /** Firings to quiescence, counted per key: a·b Pairs, a·b·c Triples, a·b·c·a Alerts. */
    long expectedFirings() {
        long total = 0;
        for (int k = 0; k * GROUP < n; k++) {
            long a = 0;
            long b = 0;
            long c = 0;
            for (int i = k * GROUP; i < Math.min(n, (k + 1) * GROUP); i++) {
                switch (stimulusClass(i)) {
                    case "StimA" -> a++;
                    case "StimB" -> b++;
                    default -> c++;
                }
            }
            total += a * b + a * b * c + a * b * c * a;
        }
        return total;
    }

    /** The K-ICNP class frames: the hierarchy and the three behavior frames. */
    List<Change> kicnpClasses() {
        List<Change> out = new ArrayList<>();
        out.add(add(Frame.classFrame("Stimulus").slot(Slot.builder("key", DataType.INTEGER).build()).build()));
        for (String kind : List.of("StimA", "StimB", "StimC")) {
            out.add(add(Frame.classFrame(kind).parent("Stimulus").build()));
        }
        out.add(add(Frame.classFrame("Derived").build()));
        out.add(add(behavior("Pair", "mA", "StimA", "mB", "StimB", ".key == mA.key")));
        out.add(add(behavior("Triple", "mP", "Pair", "mC", "StimC", ".key == mP.mA.key")));
        out.add(add(behavior("Alert", "mT", "Triple", "mA", "StimA", ".key == mT.mP.mA.key")));
        return out;
    }

    /** The N stimulus instances, as one batch for the knowledge base. */
    List<Change> kicnpStimuli() {
        List<Change> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            out.add(add(stimulus("s" + i, stimulusClass(i), key(i))));
        }
        return out;
    }

    static Frame stimulus(String name, String cls, long key) {
        return Frame.instance(name, cls).provenance(Provenance.RUNTIME)
                .slot(Slot.ofValue("key", DataType.INTEGER, Value.of(key))).build();
    }

    private static Frame behavior(String name, String first, String firstClass, String second, String secondClass,
            String join) {
        return Frame.classFrame(name).parent("Derived").priority(priority(name))
                .slot(Slot.builder(first, DataType.INSTANCE).argument(firstClass).required(true).build())
                .slot(Slot.builder(second, DataType.INSTANCE).argument(secondClass).required(true)
                        .condition(ConditionParser.parse(join)).build())
                .build();
    }

    private static Change add(Frame f) {
        return new Change.Add(f);
    }

    /** The DRL with derived facts inserted plainly ({@code insert}): they stay when what they were made from goes. */
    static String drl() {
        return drl(false);
    }

    /**
     * The same hierarchy and rules in DRL: declared types, salience = the K-ICNP priority, derived facts inserted
     * ({@code insert}) or, with {@code logical}, inserted logically ({@code insertLogical}: Drools' truth maintenance,
     * the derived fact is retracted when the match that justified it no longer holds, as K-ICNP retracts a derived
     * instance when an instance it rests on goes). Each
     * join binds the key first ({@code $k : mP.mA.key}) and compares the other fact's field to it, the form Drools
     * answers from a hash index (comparing to a path such as {@code $t.mP.mA.key} it would not index, and every join
     * would scan the other side: that would be unfair to Drools).
     */
    static String drl(boolean logical) {
        return """
                package %1$s;

                declare Stimulus
                    key : int
                end
                declare StimA extends Stimulus end
                declare StimB extends Stimulus end
                declare StimC extends Stimulus end

                declare Derived end
                declare Pair extends Derived
                    mA : StimA
                    mB : StimB
                end
                declare Triple extends Derived
                    mP : Pair
                    mC : StimC
                end
                declare Alert extends Derived
                    mT : Triple
                    mA : StimA
                end

                rule "Pair" salience %2$d when
                    $a : StimA( $k : key )
                    $b : StimB( key == $k )
                then
                    %5$s( new Pair( $a, $b ) );
                end

                rule "Triple" salience %3$d when
                    $p : Pair( $k : mA.key )
                    $c : StimC( key == $k )
                then
                    %5$s( new Triple( $p, $c ) );
                end

                rule "Alert" salience %4$d when
                    $t : Triple( $k : mP.mA.key )
                    $a : StimA( key == $k )
                then
                    %5$s( new Alert( $t, $a ) );
                end
                """.formatted(DRL_PACKAGE, priority("Pair"), priority("Triple"), priority("Alert"),
                logical ? "insertLogical" : "insert");
    }
}
