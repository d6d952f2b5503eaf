package org.kicnp.bench;

import java.util.ArrayList;
import java.util.List;

/** Timed samples of one measure; the median is reported because it shrugs off a stray slow round. */
final class Samples {
    private final List<Double> values = new ArrayList<>();

    void add(double value) {
        values.add(value);
    }

    int size() {
        return values.size();
    }

    /** The {@code i}-th value, in the order added. */
    double get(int i) {
        return values.get(i);
    }

    double median() {
        if (values.isEmpty()) {
            throw new IllegalStateException("No samples were taken, so there is no median.");
        }
        List<Double> sorted = values.stream().sorted().toList();
        int mid = sorted.size() / 2;
        return sorted.size() % 2 == 1 ? sorted.get(mid) : (sorted.get(mid - 1) + sorted.get(mid)) / 2;
    }

    double min() {
        return values.stream().mapToDouble(Double::doubleValue).min().orElseThrow();
    }

    double max() {
        return values.stream().mapToDouble(Double::doubleValue).max().orElseThrow();
    }
}
