package org.kicnp.robots;

import java.util.Arrays;
import java.util.List;

/**
 * The face space of Turk and Pentland (1991), "Eigenfaces for recognition": the mean of the training faces and the
 * leading eigenvectors of their covariance (the eigenfaces). A face is described by its weights, its projection on
 * the eigenfaces; what the projection loses is its distance from face space. Immutable; built by {@link #train}.
 */
final class Eigenfaces {
    /** Keep the leading eigenfaces that explain this share of the training variance. */
    private static final double KEPT_VARIANCE = 0.99;
    private static final int JACOBI_SWEEPS = 100;

    private final double[] mean;
    private final double[][] components;

    private Eigenfaces(double[] mean, double[][] components) {
        this.mean = mean;
        this.components = components;
    }

    /** Principal component analysis of the training faces (at least one; all of one dimension). */
    static Eigenfaces train(List<FaceVector> faces) {
        int n = faces.size();
        int d = faces.getFirst().dimension();
        double[] mean = new double[d];
        for (FaceVector f : faces) {
            for (int i = 0; i < d; i++) {
                mean[i] += f.get(i) / n;
            }
        }
        double[][] cov = new double[d][d];
        for (FaceVector f : faces) {
            for (int i = 0; i < d; i++) {
                for (int j = 0; j < d; j++) {
                    cov[i][j] += (f.get(i) - mean[i]) * (f.get(j) - mean[j]) / n;
                }
            }
        }
        double[][] vectors = new double[d][d];
        double[] values = jacobi(cov, vectors);
        Integer[] order = new Integer[d];
        Arrays.setAll(order, i -> i);
        Arrays.sort(order, (a, b) -> Double.compare(values[b], values[a]));
        double total = Arrays.stream(values).map(v -> Math.max(v, 0)).sum();
        int kept = 0;
        double explained = 0;
        while (kept < Math.min(d, n - 1) && total > 0 && explained < KEPT_VARIANCE * total) {
            explained += Math.max(values[order[kept]], 0);
            kept++;
        }
        double[][] components = new double[kept][d];
        for (int k = 0; k < kept; k++) {
            for (int i = 0; i < d; i++) {
                components[k][i] = vectors[i][order[k]];
            }
        }
        return new Eigenfaces(mean, components);
    }

    int dimension() {
        return mean.length;
    }

    /** How many eigenfaces span the face space. */
    int size() {
        return components.length;
    }

    /** The weights of a face: its coordinates on the eigenfaces, relative to the mean face. */
    double[] weights(FaceVector face) {
        double[] w = new double[components.length];
        for (int k = 0; k < components.length; k++) {
            double dot = 0;
            for (int i = 0; i < mean.length; i++) {
                dot += (face.get(i) - mean[i]) * components[k][i];
            }
            w[k] = dot;
        }
        return w;
    }

    /** The distance between a face and its reconstruction from its weights: how far it lies from face space. */
    double distanceFromFaceSpace(FaceVector face, double[] weights) {
        double sum = 0;
        for (int i = 0; i < mean.length; i++) {
            double rebuilt = mean[i];
            for (int k = 0; k < components.length; k++) {
                rebuilt += weights[k] * components[k][i];
            }
            double r = face.get(i) - rebuilt;
            sum += r * r;
        }
        return Math.sqrt(sum);
    }

    /** Cyclic Jacobi eigenvalue algorithm for a symmetric matrix: returns eigenvalues, fills eigenvector columns. */
    private static double[] jacobi(double[][] matrix, double[][] vectors) {
        int d = matrix.length;
        double[][] a = new double[d][];
        for (int i = 0; i < d; i++) {
            a[i] = matrix[i].clone();
            vectors[i][i] = 1;
        }
        for (int sweep = 0; sweep < JACOBI_SWEEPS && offDiagonal(a) > 1e-22; sweep++) {
            for (int p = 0; p < d - 1; p++) {
                for (int q = p + 1; q < d; q++) {
                    if (Math.abs(a[p][q]) < 1e-300) {
                        continue;
                    }
                    double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                    double t = Math.signum(theta == 0 ? 1 : theta) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
                    double c = 1 / Math.sqrt(t * t + 1);
                    double s = t * c;
                    rotate(a, vectors, p, q, c, s);
                }
            }
        }
        double[] values = new double[d];
        for (int i = 0; i < d; i++) {
            values[i] = a[i][i];
        }
        return values;
    }

    private static void rotate(double[][] a, double[][] v, int p, int q, double c, double s) {
        int d = a.length;
        for (int k = 0; k < d; k++) {
            double akp = a[k][p];
            double akq = a[k][q];
            a[k][p] = c * akp - s * akq;
            a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < d; k++) {
            double apk = a[p][k];
            double aqk = a[q][k];
            a[p][k] = c * apk - s * aqk;
            a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < d; k++) {
            double vkp = v[k][p];
            double vkq = v[k][q];
            v[k][p] = c * vkp - s * vkq;
            v[k][q] = s * vkp + c * vkq;
        }
    }

    private static double offDiagonal(double[][] a) {
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            for (int j = 0; j < a.length; j++) {
                if (i != j) {
                    sum += a[i][j] * a[i][j];
                }
            }
        }
        return sum;
    }
}
