package org.kicnp.inference;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.BooleanSupplier;
import java.util.function.Consumer;
import org.kicnp.core.ChangeSet;
import org.kicnp.core.Frame;
import org.kicnp.core.FrameEvent;
import org.kicnp.core.KnowledgeBase;
import org.kicnp.core.NameTable;
import org.kicnp.core.Slot;
import org.kicnp.core.Value;

/**
 * Forward chaining and truth maintenance on the engine thread: turns knowledge base events into match network
 * updates and agenda entries, fires activations, and retracts what no longer holds. {@link InferenceEngine} owns
 * the loop and the lock; this class owns the network, the agenda and the rules. What a firing does is {@link Firing};
 * how instances are taken out with what rests on them is {@link Retractions}.
 */
final class ForwardChainer {
    private final KnowledgeBase kb;
    private final Conditions conditions;
    private final RuleCompiler compiler;
    private final MatchNetwork network;
    private final Agenda agenda;
    private final Supports supports;
    private final ScriptCalls scripts;
    private final Consumer<TraceEvent> tracer;
    private final BooleanSupplier tracing;
    private final FactView facts;
    private final Map<String, Rule> rules = new LinkedHashMap<>();
    private final MadeInstances made;
    private final Retractions retractions;
    private final Firing firing;
    private long stampCounter;
    /**
     * The list {@link #factAdded} collects a new fact's bindings in, emptied after each fact and kept for the next
     * (null while one is in use): a fact that completes bindings makes no list of its own.
     */
    private List<MatchNetwork.Match> spareMatches = new ArrayList<>();
    private long seq;

    ForwardChainer(KnowledgeBase kb, FactView facts, Conditions conditions, Supports supports, ScriptCalls scripts,
                   Consumer<TraceEvent> tracer, BooleanSupplier tracing) {
        this.facts = facts;
        this.tracing = tracing;
        this.kb = kb;
        this.conditions = conditions;
        this.compiler = new RuleCompiler(kb);
        this.network = new MatchNetwork(kb, conditions, facts);
        this.agenda = new Agenda(facts);
        this.supports = supports;
        this.scripts = scripts;
        this.tracer = tracer;
        this.made = new MadeInstances(kb);
        DerivationCheck check = new DerivationCheck(kb, conditions, scripts, supports, rules);
        this.retractions = new Retractions(kb, supports, check, tracer);
        this.firing = new Firing(kb, facts, conditions, network, supports, scripts, made, check, retractions, tracer,
                tracing);
    }

    /** Stamps the instances there are and installs every behavior frame, matching what is already there. */
    void start() {
        for (Frame f : kb.frames()) {
            if (f.isInstance()) {
                facts.put(f).stamp = ++stampCounter;
            }
        }
        for (Frame f : kb.frames()) {
            if (f.isClass()) {
                install(f.name());
            }
        }
    }

    /** The activation whose turn has come, taken off the agenda; null when the agenda is empty. */
    Activation next() {
        return agenda.poll();
    }

    void clearAgenda() {
        agenda.clear();
    }

    int agendaSize() {
        return agenda.size();
    }

    List<Activation> agenda() {
        return agenda.inOrder();
    }

    List<Rule> rules() {
        return List.copyOf(rules.values());
    }

    /** The compiled rule of a behavior frame, if the frame is one. */
    Optional<Rule> rule(String frame) {
        return Optional.ofNullable(rules.get(frame));
    }

    long firings() {
        return firing.firings();
    }

    /** Applies one committed batch to the network, the agenda and the truth maintenance records. */
    void process(ChangeSet cs) {
        FactView.Fact[] prepared = prepare(cs);
        List<String> classesRemoved = new ArrayList<>(0);
        for (int i = 0; i < cs.events().size(); i++) { // by index: an iterator per change set (per firing) is garbage
            switch (cs.events().get(i)) {
                case FrameEvent.Added a -> {
                    if (a.frame().isInstance()) {
                        factAdded(a.frame(), prepared == null ? null : prepared[i]);
                    } else {
                        network.classesChanged();
                        classChanged(a.name());
                    }
                }
                case FrameEvent.Replaced r -> {
                    if (r.frame().isInstance() && r.before_().isInstance()) {
                        factReplaced(r.before_(), r.frame());
                    } else {
                        if (r.before_().isInstance()) {
                            factRemoved(r.before_());
                        }
                        network.classesChanged();
                        classChanged(r.name());
                        if (r.frame().isClass() && r.before_().isClass() && (!r.before_().parent()
                                .equals(r.frame().parent()) || !r.before_().slots().equals(r.frame().slots()))) {
                            rematchAll(kb.instancesOf(r.name()).stream().map(Frame::name).toList(),
                                    "class '" + r.name() + "' changed");
                        }
                    }
                }
                case FrameEvent.Removed rm -> {
                    if (rm.frame().isInstance()) {
                        factRemoved(rm.frame());
                    } else {
                        classesRemoved.add(rm.name());
                    }
                }
            }
        }
        // After the batch's instances: a frame removed with its instances still retracts them as its rule says
        // (their onDestroy runs), whatever order the batch named them in.
        for (String name : classesRemoved) {
            network.classesChanged();
            uninstall(name);
        }
    }

    /**
     * For a large batch of new instances (a burst of sensor readings): grows the fact records and the memories the
     * instances will enter once, not step by step, then makes the record of each new instance; returns them by the
     * event's index (null: a small batch). Made in one loop, the look-ups into the records' name table overlap their
     * cache misses, where made one per fact between its matching they came one after the other (the engine's name
     * table cost twice the knowledge base's for the same stimuli, which the knowledge base puts in one loop). A record
     * made here is used unless its fact has left by the time its event comes ({@link FactView.Fact#gone}): a change set
     * has one event per name, so it cannot do that itself, but the check costs a field read.
     */
    private FactView.Fact[] prepare(ChangeSet cs) {
        List<FrameEvent> events = cs.events();
        if (events.size() < 64) {
            return null;
        }
        int hashed = 0;
        int numbered = 0;
        Map<String, int[]> perClass = new HashMap<>();
        for (int i = 0; i < events.size(); i++) {
            if (events.get(i) instanceof FrameEvent.Added a && a.frame().isInstance()) {
                if (NameTable.numberOf(a.frame()) < 0) {
                    hashed++;
                } else {
                    numbered++;
                }
                perClass.computeIfAbsent(a.frame().parent().orElseThrow(), c -> new int[1])[0]++;
            }
        }
        if (hashed + numbered == 0) {
            return null;
        }
        facts.ensureRoom(hashed, numbered);
        perClass.forEach((cls, count) -> network.expect(cls, count[0]));
        FactView.Fact[] prepared = new FactView.Fact[events.size()];
        for (int i = 0; i < events.size(); i++) {
            if (events.get(i) instanceof FrameEvent.Added a && a.frame().isInstance()) {
                prepared[i] = facts.touch(a.name(), NameTable.numberOf(a.frame()));
            }
        }
        return prepared;
    }

    // ---- facts ----

    /** An instance was added; {@code prepared}: its record, made before the batch's events were handled, or null. */
    private void factAdded(Frame f, FactView.Fact prepared) {
        long stamp = ++stampCounter;
        String cls = f.parent().orElseThrow();
        FactView.Fact fact = made.take(f);
        if (fact == null) {
            fact = prepared != null && !prepared.gone() ? prepared
                    : facts.touch(f.name(), NameTable.numberOf(f)); // the number the knowledge base read off the name
        }
        fact.seen(f);
        fact.stamp = stamp;
        scripts.forget(f.name()); // a name used again: nothing kept of the instance that had it
        if (tracing.getAsBoolean()) {
            trace(new TraceEvent.FactAsserted(f.name(), cls, stamp));
        }
        List<MatchNetwork.Match> matches = spareMatches != null ? spareMatches : new ArrayList<>();
        spareMatches = null; // were this ever entered again while it considers, the inner call would make its own
        try {
            network.insert(fact, cls, matches);
            for (int i = 0; i < matches.size(); i++) {
                consider(matches.get(i));
            }
        } finally {
            matches.clear();
            spareMatches = matches;
        }
    }

    private void factRemoved(Frame f) {
        String name = f.name();
        trace(new TraceEvent.FactRemoved(name));
        scripts.forget(name);
        network.retract(name);
        agenda.withdrawFact(name);
        supports.factGone(name);
        Set<String> orphans = supports.closure(name);
        Optional<Derivation> d = supports.release(name);
        if (d.isPresent()) {
            scripts.retracted(name);
            boolean failed = supports.takeFailed(name);
            Rule r = rules.get(d.get().frame());
            if (!failed) {
                Optional<String> onDestroy = r != null ? r.onDestroy() : kb.frame(d.get().frame())
                        .flatMap(c -> kb.value(c.name(), "onDestroy")).map(Value::text);
                onDestroy.ifPresent(src -> scripts.run(d.get().frame(), "onDestroy", src, scripts.snapshot(f), name,
                        Optional.empty()));
            }
            if (r != null) {
                d.get().binding().forEach((slot, fact) -> network.rematch(r.frame(), slot, fact).forEach(this::reconsider));
            }
        }
        retractions.removeQuietly(orphans, "it rests on '" + name + "', which was removed");
        facts.remove(name);
    }

    private void factReplaced(Frame before, Frame after) {
        String name = after.name();
        facts.put(after);
        scripts.forget(name);
        Set<String> changed = changedSlots(before, after);
        scripts.runDemons(before, after, changed);
        String cls = after.parent().orElseThrow();
        boolean reactive = !before.parent().equals(after.parent()) || changed.stream().anyMatch(s ->
                kb.slot(cls, s).map(e -> e.slot().reactive()).orElse(true));
        if (!kb.contains(name)) {
            return;
        }
        if (!reactive) {
            reindex(name); // nothing is matched again, but facts that come later meet it as it is now
            return;
        }
        rematch(name, "'" + name + "' changed");
    }

    /**
     * Brings the memberships and index keys of a changed instance, and of every instance that reads it through a
     * reference, up to date without matching them again ({@link MatchNetwork#refresh}).
     */
    private void reindex(String name) {
        refresh(name);
        forEachReader(name, new LinkedHashSet<>(List.of(name)), this::refresh);
    }

    private void refresh(String name) {
        scripts.forget(name); // it, or an instance it reads through, changed
        FactView.Fact f = facts.get(name);
        if (f != null) {
            for (Activation a : f.activations()) {
                a.changed = true; // what waits with it is checked again before it fires, not matched again now
            }
        }
        kb.frame(name).filter(Frame::isInstance).flatMap(Frame::parent).ifPresent(cls -> network.refresh(name, cls));
    }

    /**
     * Matches an instance again after it (or its class) changed: it leaves every memory, derived instances that rest
     * on it are re-checked (and retracted when a condition no longer holds), and it enters again as a recent fact.
     */
    private void rematch(String name, String why) {
        rematchOne(name, why);
        rematchReaders(name, why, new LinkedHashSet<>(List.of(name)));
    }

    /**
     * As {@link #rematch} for every instance of an edited class (they may inherit other values now), then, once
     * each, every instance that reads one of them through references.
     */
    private void rematchAll(List<String> names, String why) {
        names.forEach(n -> rematchOne(n, why));
        Set<String> seen = new LinkedHashSet<>(names);
        names.forEach(n -> rematchReaders(n, why, seen));
    }

    /**
     * A changed instance may be read through: a condition or an index path such as {@code mP.mA.key} reaches it from
     * an instance that refers to it. Every instance referring to it, directly or through others, is matched again,
     * so that indexes are rebuilt and the conditions of what was derived from them are checked again (and the
     * derived instances retracted where they no longer hold).
     */
    private void rematchReaders(String name, String why, Set<String> seen) {
        forEachReader(name, seen, r -> rematchOne(r, why + " (read through '" + r + "')"));
    }

    /**
     * Visits, once each, every instance the engine holds that refers to {@code name}, directly or through others;
     * those in {@code seen} are skipped, and each visited one is added to it.
     */
    private void forEachReader(String name, Set<String> seen, Consumer<String> visit) {
        List<String> todo = new ArrayList<>(kb.referrers(name));
        for (int i = 0; i < todo.size(); i++) {
            String r = todo.get(i);
            FactView.Fact f = facts.get(r);
            if (!seen.add(r) || f == null || f.frame == null) {
                continue;
            }
            visit.accept(r);
            todo.addAll(kb.referrers(r));
        }
    }

    private void rematchOne(String name, String why) {
        Optional<Frame> now = kb.frame(name);
        if (now.isEmpty() || !now.get().isInstance()) {
            return;
        }
        trace(new TraceEvent.FactChanged(name));
        scripts.forget(name); // it, its class or an instance it reads through changed
        network.retract(name);
        agenda.withdrawFact(name);
        for (String dep : supports.dependentsOf(name)) {
            supports.derivation(dep).filter(d -> d.binding().containsValue(name)).ifPresent(d ->
                    retractions.retractIfFailing(dep, d, slot -> "the condition of slot '" + slot + "' of '"
                            + d.frame() + "' no longer holds after " + why));
        }
        facts.touch(name).stamp = ++stampCounter;
        network.insert(name, now.get().parent().orElseThrow()).forEach(this::consider);
    }

    private static Set<String> changedSlots(Frame before, Frame after) {
        Set<String> names = new LinkedHashSet<>();
        before.slots().forEach(s -> names.add(s.name()));
        after.slots().forEach(s -> names.add(s.name()));
        names.removeIf(n -> before.ownSlot(n).flatMap(Slot::effectiveValue)
                .equals(after.ownSlot(n).flatMap(Slot::effectiveValue)));
        return names;
    }

    // ---- rules ----

    private void classChanged(String name) {
        if (!kb.contains(name)) {
            return;
        }
        List<String> todo = new ArrayList<>(List.of(name));
        for (int i = 0; i < todo.size(); i++) {
            for (Frame c : kb.children(todo.get(i))) {
                if (c.isClass()) {
                    todo.add(c.name());
                }
            }
        }
        todo.forEach(this::install);
    }

    private void install(String frame) {
        uninstall(frame);
        Set<String> derived = supports.derivedFrom(frame);
        compiler.compile(frame).ifPresent(r -> {
            rules.put(frame, r);
            // Its slots' order and facets may have changed: before matching, what its instances fired stays
            // refracted and what they hold is claimed again; one that claims what an older one holds no longer fits.
            List<String> fired = derived.stream().filter(i -> supports.derivation(i)
                    .map(d -> d.createdBy().isEmpty()).orElse(false)).toList();
            supports.refract(r, fired);
            Map<String, String> conflicts = supports.reclaim(r, fired);
            network.addRule(r).forEach(this::consider);
            conflicts.forEach((i, why) -> {
                Set<String> all = new LinkedHashSet<>(List.of(i));
                all.addAll(supports.closure(i));
                retractions.removeQuietly(all, "frame '" + frame + "' changed and its " + why);
            });
        });
        for (String dep : derived) {
            supports.derivation(dep).ifPresent(d -> retractions.retractIfFailing(dep, d, slot -> "frame '" + frame
                    + "' changed and the condition of slot '" + slot + "' no longer holds"));
        }
    }

    private void uninstall(String frame) {
        scripts.forgetFrame(frame); // its script conditions may be others now, or gone
        if (rules.remove(frame) != null) {
            network.removeRule(frame);
            agenda.withdrawRule(frame);
        }
    }

    // ---- matching and firing ----

    /** Considers a binding made by a new fact: new, so it cannot be waiting on the agenda already. */
    private void consider(MatchNetwork.Match m) {
        consider(m, false);
    }

    /** Considers a binding matched again (after a claim on it was freed): it may be waiting already. */
    private void reconsider(MatchNetwork.Match m) {
        consider(m, true);
    }

    private void consider(MatchNetwork.Match m, boolean mayRepeat) {
        Rule r = m.rule();
        FactView.Fact[] refs = m.refs();
        String[] bound = new String[refs.length];
        long recency = 0;
        for (int i = 0; i < refs.length; i++) {
            bound[i] = refs[i].name;
            recency = Math.max(recency, refs[i].stamp);
        }
        BindingKey key = new BindingKey(r.frame(), bound);
        if (mayRepeat && agenda.contains(key, refs)) {
            return;
        }
        boolean tracing = this.tracing.getAsBoolean();
        if (tracing) {
            trace(new TraceEvent.Matched(r.frame(), m.binding()));
        }
        Optional<String> blocked = supports.blocked(r, bound, refs[0], key);
        if (blocked.isEmpty() && r.scripted()) {
            blocked = scripts.conditionFails(r, m.binding());
        }
        if (blocked.isPresent()) {
            trace(new TraceEvent.Blocked(r.frame(), m.binding(), blocked.get()));
            return;
        }
        Activation a = new Activation(r, bound, refs, recency, ++seq, key);
        agenda.add(a);
        if (tracing) {
            trace(new TraceEvent.Activated(r.frame(), m.binding(), agenda.size()));
        }
    }

    /**
     * Whether an activation whose turn has come may still fire ({@link Firing#mayFire}); a blocked one is traced and
     * is not a firing.
     */
    boolean mayFire(Activation a) {
        return firing.mayFire(a);
    }

    /** Fires one activation that {@link #mayFire may fire} ({@link Firing#fire}). */
    /** Fires {@code a}, whose instance rests {@code depth} deep ({@link Derivation#depthOver}). */
    void fire(Activation a, int depth) {
        firing.fire(a, depth);
    }

    // ---- truth maintenance ----

    /** Removes an instance and every live instance resting on it, in one batch; returns the names. */
    Set<String> destroyNow(String instance, String reason) {
        return retractions.destroyNow(instance, reason);
    }

    /** As {@link #destroyNow(String, String)}, only while the instance is at {@code expectedRevision}. */
    Set<String> destroyNow(String instance, String reason, long expectedRevision) {
        return retractions.destroyNow(instance, reason, expectedRevision);
    }

    /** The next {@code Prefix-N} name that no frame has now (for instances that scripts create). */
    String freshName(String prefix) {
        return made.fresh(prefix);
    }

    private void trace(TraceEvent e) {
        tracer.accept(e);
    }
}
