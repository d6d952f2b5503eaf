package org.kicnp.robots;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * A face descriptor: the simulator's stand-in for a face image, a short vector of reals (16 in {@code kicnp-sim/1})
 * that stays close for one person across sightings and far between people. Immutable.
 */
public final class FaceVector {
    private final double[] values;

    private FaceVector(double[] values) {
        if (values.length == 0) {
            throw new IllegalArgumentException("A face vector needs at least one component.");
        }
        for (double v : values) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("A face vector component is not finite: " + Arrays.toString(values));
            }
        }
        this.values = values;
    }

    public static FaceVector of(List<Double> values) {
        Objects.requireNonNull(values, "values");
        return new FaceVector(values.stream().mapToDouble(Double::doubleValue).toArray());
    }

    public static FaceVector of(double... values) {
        return new FaceVector(values.clone());
    }

    public int dimension() {
        return values.length;
    }

    public double get(int i) {
        return values[i];
    }

    /** A copy of the components. */
    public double[] toArray() {
        return values.clone();
    }

    public List<Double> toList() {
        List<Double> out = new ArrayList<>(values.length);
        for (double v : values) {
            out.add(v);
        }
        return List.copyOf(out);
    }

    /** Euclidean distance; both vectors must have the same dimension. */
    public double distanceTo(FaceVector other) {
        requireSameDimension(other);
        double sum = 0;
        for (int i = 0; i < values.length; i++) {
            double d = values[i] - other.values[i];
            sum += d * d;
        }
        return Math.sqrt(sum);
    }

    void requireSameDimension(FaceVector other) {
        if (other.values.length != values.length) {
            throw new IllegalArgumentException("Face vectors of dimension " + values.length + " and "
                    + other.values.length + " cannot be compared.");
        }
    }

    @Override public boolean equals(Object o) {
        return o instanceof FaceVector f && Arrays.equals(values, f.values);
    }

    @Override public int hashCode() {
        return Arrays.hashCode(values);
    }

    @Override public String toString() {
        return Arrays.toString(values);
    }
}
