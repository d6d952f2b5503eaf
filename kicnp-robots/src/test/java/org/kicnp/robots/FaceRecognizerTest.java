package org.kicnp.robots;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

/** Eigenface recognition over 16-component descriptors with the simulator's noise (σ = 0.05). */
class FaceRecognizerTest {
    private final Random random = new Random(1991);

    private FaceVector randomFace() {
        double[] v = new double[16];
        double norm = 0;
        for (int i = 0; i < v.length; i++) {
            v[i] = random.nextGaussian();
            norm += v[i] * v[i];
        }
        for (int i = 0; i < v.length; i++) {
            v[i] /= Math.sqrt(norm);
        }
        return FaceVector.of(v);
    }

    private FaceVector noisy(FaceVector face) {
        double[] v = face.toArray();
        for (int i = 0; i < v.length; i++) {
            v[i] += 0.05 * random.nextGaussian();
        }
        return FaceVector.of(v);
    }

    @Test
    void recognize_samePersonWithNoise_isRecognisedAmongSeveral() {
        FaceRecognizer recognizer = FaceRecognizer.create();
        FaceVector alice = randomFace();
        FaceVector bob = randomFace();
        recognizer.enroll("alice", noisy(alice));
        recognizer.enroll("bob", noisy(bob));
        recognizer.enroll("carol", noisy(randomFace()));

        for (int i = 0; i < 20; i++) {
            assertThat(recognizer.recognize(noisy(alice))).hasValueSatisfying(m -> assertThat(m.name()).isEqualTo("alice"));
            assertThat(recognizer.recognize(noisy(bob))).hasValueSatisfying(m -> assertThat(m.name()).isEqualTo("bob"));
        }
    }

    @Test
    void recognize_aStranger_isUnknown() {
        FaceRecognizer recognizer = FaceRecognizer.create();
        recognizer.enroll("alice", noisy(randomFace()));
        recognizer.enroll("bob", noisy(randomFace()));

        for (int i = 0; i < 20; i++) {
            FaceVector stranger = noisy(randomFace());
            assertThat(recognizer.recognize(stranger)).isEmpty();
            assertThat(recognizer.nearest(stranger)).hasValueSatisfying(m -> assertThat(m.distance()).isGreaterThan(0.6));
        }
    }

    @Test
    void recognize_withNobodyEnrolled_isUnknown() {
        assertThat(FaceRecognizer.create().recognize(randomFace())).isEmpty();
    }

    @Test
    void recognize_atTheThreshold_matchesAndJustBeyondItDoesNot() {
        FaceVector origin = FaceVector.of(new double[16]);
        double[] shifted = new double[16];
        shifted[3] = 0.5;
        FaceRecognizer inclusive = FaceRecognizer.create(0.5);
        inclusive.enroll("alice", origin);
        FaceRecognizer strict = FaceRecognizer.create(0.4999);
        strict.enroll("alice", origin);

        assertThat(inclusive.recognize(FaceVector.of(shifted))).hasValueSatisfying(m -> {
            assertThat(m.name()).isEqualTo("alice");
            assertThat(m.distance()).isCloseTo(0.5, org.assertj.core.data.Offset.offset(1e-9));
        });
        assertThat(strict.recognize(FaceVector.of(shifted))).isEmpty();
    }

    @Test
    void nearest_distanceInFaceSpacePlusFromFaceSpace_equalsThePlainDistanceToAnEnrolledFace() {
        FaceRecognizer recognizer = FaceRecognizer.create();
        FaceVector alice = randomFace();
        recognizer.enroll("alice", alice);
        recognizer.enroll("bob", randomFace());
        recognizer.enroll("carol", randomFace());
        FaceVector probe = noisy(alice);

        assertThat(recognizer.nearest(probe).orElseThrow().distance())
                .isCloseTo(probe.distanceTo(alice), org.assertj.core.data.Offset.offset(1e-6));
    }

    @Test
    void forget_aPerson_makesTheirFaceUnknown() {
        FaceRecognizer recognizer = FaceRecognizer.create();
        FaceVector alice = randomFace();
        recognizer.enroll("alice", alice);
        recognizer.forget("alice");

        assertThat(recognizer.recognize(alice)).isEmpty();
        assertThat(recognizer.names()).isEmpty();
    }

    @Test
    void enroll_aFaceOfAnotherDimension_isRefused() {
        FaceRecognizer recognizer = FaceRecognizer.create();
        recognizer.enroll("alice", randomFace());

        assertThatThrownBy(() -> recognizer.enroll("bob", FaceVector.of(1, 2, 3)))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("Face vectors of dimension 16 and 3 cannot be compared.");
    }
}
