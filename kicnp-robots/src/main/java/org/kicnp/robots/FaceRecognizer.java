package org.kicnp.robots;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * Robovie's face recogniser, the eigenface method of Turk and Pentland (1991) applied to the simulator's face
 * descriptors. Enrolled faces train a face space ({@link Eigenfaces}); each person is the mean of their faces'
 * weights. A face is projected into the space and matched with the nearest person, its distance combining the
 * distance in face space with the distance from face space; within {@link #threshold()} it is that person,
 * otherwise a stranger. Thread-safe: the face space is retrained lazily after each change.
 */
public final class FaceRecognizer {
    /** With the simulator's noise (σ 0.05 on each of 16 components), one person's sightings lie about 0.3 apart. */
    public static final double DEFAULT_THRESHOLD = 0.6;

    private final double threshold;
    private final Map<String, List<FaceVector>> faces = new LinkedHashMap<>();
    private Trained trained;

    private FaceRecognizer(double threshold) {
        if (!(threshold > 0)) {
            throw new IllegalArgumentException("Face threshold " + threshold + " must be positive.");
        }
        this.threshold = threshold;
    }

    public static FaceRecognizer create(double threshold) {
        return new FaceRecognizer(threshold);
    }

    public static FaceRecognizer create() {
        return new FaceRecognizer(DEFAULT_THRESHOLD);
    }

    /** The largest distance at which a face is still taken for a known person. */
    public double threshold() {
        return threshold;
    }

    /** Adds a face of {@code name}; several faces of one person are averaged in face space. */
    public synchronized void enroll(String name, FaceVector face) {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(face, "face");
        faces.values().stream().flatMap(List::stream).findFirst().ifPresent(any -> any.requireSameDimension(face));
        faces.computeIfAbsent(name, n -> new ArrayList<>()).add(face);
        trained = null;
    }

    /** Forgets every face of {@code name}; a no-op for a name not enrolled. */
    public synchronized void forget(String name) {
        if (faces.remove(Objects.requireNonNull(name, "name")) != null) {
            trained = null;
        }
    }

    public synchronized Set<String> names() {
        return Set.copyOf(faces.keySet());
    }

    /** The known person this face belongs to, if the nearest one lies within the threshold. */
    public Optional<Match> recognize(FaceVector face) {
        return nearest(face).filter(m -> m.distance() <= threshold);
    }

    /** The nearest known person whatever the distance; empty when nobody is enrolled. */
    public synchronized Optional<Match> nearest(FaceVector face) {
        Objects.requireNonNull(face, "face");
        if (faces.isEmpty()) {
            return Optional.empty();
        }
        if (trained == null) {
            trained = train();
        }
        if (face.dimension() != trained.space.dimension()) {
            throw new IllegalArgumentException("Face of dimension " + face.dimension() + " cannot be compared with "
                    + "enrolled faces of dimension " + trained.space.dimension() + ".");
        }
        double[] w = trained.space.weights(face);
        double fromSpace = trained.space.distanceFromFaceSpace(face, w);
        Match best = null;
        for (Map.Entry<String, double[]> person : trained.classes.entrySet()) {
            double inSpace = euclid(w, person.getValue());
            double d = Math.sqrt(inSpace * inSpace + fromSpace * fromSpace);
            if (best == null || d < best.distance()) {
                best = new Match(person.getKey(), d);
            }
        }
        return Optional.of(best);
    }

    private Trained train() {
        List<FaceVector> all = faces.values().stream().flatMap(List::stream).toList();
        Eigenfaces space = Eigenfaces.train(all);
        Map<String, double[]> classes = new LinkedHashMap<>();
        faces.forEach((name, list) -> {
            double[] mean = new double[space.size()];
            for (FaceVector f : list) {
                double[] w = space.weights(f);
                for (int k = 0; k < w.length; k++) {
                    mean[k] += w[k] / list.size();
                }
            }
            classes.put(name, mean);
        });
        return new Trained(space, classes);
    }

    private static double euclid(double[] a, double[] b) {
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            sum += (a[i] - b[i]) * (a[i] - b[i]);
        }
        return Math.sqrt(sum);
    }

    /** A recognised person and how far the face was from them. */
    public record Match(String name, double distance) {
        public Match {
            Objects.requireNonNull(name, "name");
        }
    }

    private record Trained(Eigenfaces space, Map<String, double[]> classes) { }
}
