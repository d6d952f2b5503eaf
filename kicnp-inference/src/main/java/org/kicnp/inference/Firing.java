package org.kicnp.inference;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import org.kicnp.core.DataType;
import org.kicnp.core.Frame;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.KnowledgeException;
import org.kicnp.core.Provenance;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Fires the activation whose turn has come: checks that it still may, names and creates the derived instance,
 * records its derivation and runs its {@code onInstantiate} script. Kept apart from {@link ForwardChainer}, which
 * turns knowledge base events into matches and agenda entries: this is the step that acts on a match, the one place
 * a firing writes to the knowledge base.
 */
final class Firing {
    private final KnowledgeBase kb;
    private final FactView facts;
    private final Conditions conditions;
    private final MatchNetwork network;
    private final Supports supports;
    private final ScriptCalls scripts;
    private final MadeInstances made;
    private final DerivationCheck check;
    private final Retractions retractions;
    private final Consumer<TraceEvent> tracer;
    private final BooleanSupplier tracing;
    private long firings;
    /**
     * The arrays a firing hands {@link KnowledgeBase#addInstance} (the values of the new instance's slots and the
     * frames they name), one pair per number of required slots: the knowledge base keeps neither, so a firing fills
     * them instead of making two arrays, and empties them once the add returns.
     */
    private Value[][] valueScratch = new Value[4][];
    private Frame[][] frameScratch = new Frame[4][];

    Firing(KnowledgeBase kb, FactView facts, Conditions conditions, MatchNetwork network, Supports supports,
           ScriptCalls scripts, MadeInstances made, DerivationCheck check, Retractions retractions,
           Consumer<TraceEvent> tracer, BooleanSupplier tracing) {
        this.kb = kb;
        this.facts = facts;
        this.conditions = conditions;
        this.network = network;
        this.supports = supports;
        this.scripts = scripts;
        this.made = made;
        this.check = check;
        this.retractions = retractions;
        this.tracer = tracer;
        this.tracing = tracing;
    }

    /** The firings so far: the number of the last one. */
    long firings() {
        return firings;
    }

    /**
     * Whether an activation whose turn has come may still fire: an earlier firing may have claimed one of its
     * instances or taken its key since it was made, or a non-reactive change to one of them made a condition false
     * (then it is traced as blocked, and it is not a firing). Conditions are checked again only after such a change.
     */
    boolean mayFire(Activation a) {
        Optional<String> blocked = supports.blocked(a.rule(), a.facts(), a.refs()[0], a.key());
        if (blocked.isEmpty() && a.changed) {
            blocked = check.failing(a.rule(), a.binding())
                    .map(why -> why + ": a bound instance changed while the binding waited on the agenda");
        }
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(a.rule().frame(), a.binding(), blocked.get()));
            return false;
        }
        return true;
    }

    /**
     * Fires one activation that {@link #mayFire may fire}: creates the instance, {@code depth} deep
     * ({@link Derivation#depthOver}, which the run has checked against its limit), and runs its onInstantiate script.
     */
    void fire(Activation a, int depth) {
        Rule r = a.rule();
        FactView.Fact[] refs = a.refs();
        // A rule with no optional slot (most) binds its required slots only: the derivation takes the activation's
        // arrays and the values tested, with no binding map or list of conditions made for it.
        boolean plain = r.optional().isEmpty();
        Map<String, String> full = plain ? null : withOptional(r, a.binding());
        String trigger = newest(refs, full);
        Object tested = plain ? CheckedConditions.kept(r, refs, facts, conditions) : null;
        List<Derivation.CheckedCondition> checked = plain ? null : CheckedConditions.of(r, full, refs, facts,
                conditions);
        long firing = ++firings;
        supports.markFired(a.key(), refs); // refracted even when the instance cannot be made
        String name;
        while (true) {
            name = made.next(r.frame());
            Derivation d = plain
                    ? new Derivation(name, a.key(), r.requiredSlots(), r.required(), tested, firing, trigger, depth)
                    : new Derivation(name, r.frame(), full, checked, firing, trigger, Optional.empty(), depth);
            FactView.Fact record = supports.record(d, r, refs, made.number());
            try {
                if (d.width() == refs.length) {
                    addInstance(r, name, refs);
                    // Its slots hold the required slots' facts in order: refs (shared: the activation is done with).
                    // Set after the add, yet before the engine handles its event (that waits for the next drain),
                    // which gives the record this frame (Fact#seen keeps links given for the frame to come).
                    record.links = refs;
                } else {
                    kb.add(Frame.instance(name, r.frame(), Provenance.RUNTIME, slotsOf(full)),
                            framesOf(refs, new Frame[refs.length]));
                }
                made.added(record);
                break;
            } catch (KnowledgeException e) {
                supports.release(name);
                if (kb.contains(name)) {
                    continue; // a frame the engine did not make has this name: take the next one
                }
                trace(new TraceEvent.Blocked(r.frame(), plain ? a.binding() : full,
                        "the instance could not be created: " + e.getMessage()));
                return;
            }
        }
        if (tracing.getAsBoolean()) {
            trace(new TraceEvent.Fired(r.frame(), name, plain ? a.binding() : full, firings));
        }
        Optional<String> script = r.onInstantiate();
        if (script.isPresent()) {
            boolean ok = scripts.run(r.frame(), "onInstantiate", script.get(), new FrameView(kb, name, 0), name,
                    Optional.of(name));
            if (!ok) {
                supports.markFailed(name);
                retractions.removeQuietly(List.of(name), "its onInstantiate script failed");
            }
        }
    }

    /** The slots of a firing's instance that binds optional slots: each slot of the binding, in its order. */
    private static Slot[] slotsOf(Map<String, String> full) {
        Slot[] slots = new Slot[full.size()];
        int i = 0;
        for (Map.Entry<String, String> e : full.entrySet()) {
            slots[i++] = Slot.ofValue(e.getKey(), DataType.INSTANCE, Value.ref(e.getValue()));
        }
        return slots;
    }

    /**
     * Adds the instance of a firing that binds only required slots, through the frame's shape: the values are a
     * reference to each bound fact, in order, and the frames at hand those the engine last saw for them.
     */
    private Frame addInstance(Rule r, String name, FactView.Fact[] refs) {
        int n = refs.length;
        if (n >= valueScratch.length) {
            valueScratch = Arrays.copyOf(valueScratch, n + 1);
            frameScratch = Arrays.copyOf(frameScratch, n + 1);
        }
        Value[] values = valueScratch[n];
        Frame[] frames = frameScratch[n];
        if (values == null) {
            values = valueScratch[n] = new Value[n];
            frames = frameScratch[n] = new Frame[n];
        }
        for (int i = 0; i < n; i++) {
            values[i] = refs[i].ref();
        }
        try {
            return kb.addInstance(r.shape(), name, values, framesOf(refs, frames));
        } finally {
            Arrays.fill(values, null); // nothing kept alive by a scratch array between firings
            Arrays.fill(frames, null);
        }
    }

    /**
     * The bound facts' frames as the engine last saw them (null where it has none), those the new instance names,
     * put in {@code out} (as long as {@code refs}) and returned.
     */
    private static Frame[] framesOf(FactView.Fact[] refs, Frame[] out) {
        for (int i = 0; i < refs.length; i++) {
            out[i] = refs[i].frame;
        }
        return out;
    }

    /** The most recently asserted instance of a binding: the required slots' records, then any optional ones. */
    private String newest(FactView.Fact[] refs, Map<String, String> full) { // full: null for required slots only
        String trigger = null;
        long newest = -1;
        for (FactView.Fact f : refs) {
            if (f.stamp > newest) {
                newest = f.stamp;
                trigger = f.name;
            }
        }
        if (full != null && full.size() > refs.length) {
            for (String f : full.values()) {
                long st = facts.stamp(f);
                if (st > newest) {
                    newest = st;
                    trigger = f;
                }
            }
        }
        return trigger;
    }

    /** The binding with each optional slot bound to the newest instance that fits it, where one does. */
    private Binding withOptional(Rule r, Binding required) {
        Map<String, String> full = new LinkedHashMap<>(required);
        for (SlotPattern p : r.optional()) {
            String best = null;
            for (String c : network.candidates(r.frame(), p.slot())) {
                if (full.containsValue(c) || (p.claims() && supports.consumed(r.frame(), p.slot(), c))) {
                    continue;
                }
                Map<String, String> trial = new LinkedHashMap<>(full);
                trial.put(p.slot(), c);
                if (conditions.holds(p.condition(), Value.ref(c), r.frame(), trial)
                        && (best == null || facts.stamp(c) > facts.stamp(best))) {
                    best = c;
                }
            }
            if (best != null) {
                full.put(p.slot(), best);
            }
        }
        return Binding.copyOf(full);
    }

    private void trace(TraceEvent e) {
        tracer.accept(e);
    }
}
