package org.kicnp.cli.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.kicnp.cli.scenario.RunRecord.Step;

/**
 * The checks of a finished first visit of Table 5, as sentences naming what went wrong (empty when all hold): the
 * rows in order, every robot action ended with feedback, succession order, the synchronized pair started within
 * {@link #SKEW_MS}, and nothing else sent while Scout hands over the cup (restriction).
 */
public final class Table5Checks {
    /** The largest start-time difference allowed between synchronized actions. */
    public static final long SKEW_MS = 250;

    /** Robovie's lines in Table 5, in order (XXX stands for the user's name). */
    public static final List<String> LINES = List.of(
            "How are you! I have never seen you before. What is your name?",
            "Hi, XXX. Nice to meet you. Welcome you to visit my room.",
            "This is my friend, PINO.",
            "What do you want to drink?",
            "This is a robot dog AIBO. Please enjoy yourself with it.");

    /** The behavior frames whose actions carry out Table 5's rows, in order. */
    public static final List<String> ROWS = List.of("FirstMeet", "AskUserName", "Welcome", "ShakeBothHands",
            "IntroducePino", "PinoWalk", "PinoGreetsUser", "AskDrink", "ScoutToKitchen", "ScoutToCup", "ScoutTakesCup",
            "ScoutBring", "ScoutServesCup", "IntroduceAibo", "AIBOAction1", "AIBOAction2");

    /** Pairs that must follow each other: each frame's action is sent only after the one before it ended. */
    private static final List<String> SUCCESSION = List.of("AskUserName", "Welcome", "ShakeBothHands", "IntroducePino",
            "PinoGreetsUser", "AskDrink", "ScoutToKitchen", "ScoutToCup", "ScoutTakesCup", "ScoutBring",
            "ScoutServesCup", "IntroduceAibo", "AIBOAction1", "AIBOAction2");

    private Table5Checks() {
    }

    public static List<String> problems(RunRecord r, String name) {
        List<String> out = new ArrayList<>();
        List<String> lines = r.lines();
        int at = 0;
        for (String expected : LINES) {
            String line = expected.replace("XXX", name);
            int i = lines.subList(at, lines.size()).indexOf(line);
            if (i < 0) {
                out.add("Robovie did not say \"" + line + "\" after the line before it.");
            } else {
                at += i + 1;
            }
        }
        List<String> order = r.steps().stream().map(Step::frame).filter(ROWS::contains).distinct().toList();
        if (!order.equals(ROWS)) {
            out.add("The rows ran in the order " + order + ", not " + ROWS + ".");
        }
        for (Step s : r.steps()) {
            if (!s.ended()) {
                out.add("The action " + s.action() + " of " + s.robot() + " (" + s.frame() + ") did not end: "
                        + (s.outcome().isEmpty() ? "no feedback" : s.outcome() + " " + s.detail()) + ".");
            }
        }
        for (int i = 1; i < SUCCESSION.size(); i++) {
            Optional<Step> before = first(r, SUCCESSION.get(i - 1));
            Optional<Step> after = first(r, SUCCESSION.get(i));
            if (before.isPresent() && after.isPresent() && after.get().sent() < before.get().finished()) {
                out.add(SUCCESSION.get(i) + " was sent before " + SUCCESSION.get(i - 1) + " had ended.");
            }
        }
        syncSkewMillis(r).filter(ms -> ms > SKEW_MS).ifPresent(ms -> out.add(
                "\"This is my friend, PINO.\" and PINO's walk started " + ms + " ms apart (allowed " + SKEW_MS + ")."));
        first(r, "ScoutServesCup").ifPresent(hand -> r.steps().stream()
                .filter(s -> !s.id().equals(hand.id()) && s.sent() > hand.sent() && s.sent() < hand.finished())
                .forEach(s -> out.add(s.frame() + " was sent while Scout handed over the cup (restriction).")));
        return out;
    }

    /** How far apart the two synchronized actions started (robot feedback "started"), in ms, if both did. */
    public static Optional<Long> syncSkewMillis(RunRecord r) {
        Optional<Step> intro = first(r, "IntroducePino");
        Optional<Step> walk = first(r, "PinoWalk");
        return intro.isPresent() && walk.isPresent() && intro.get().started() > 0 && walk.get().started() > 0
                ? Optional.of(Math.abs(intro.get().started() - walk.get().started()) / 1_000_000) : Optional.empty();
    }

    private static Optional<Step> first(RunRecord r, String frame) {
        return r.stepsOf(frame).stream().findFirst();
    }
}
