package org.kicnp.editor;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;

class LoginThrottleTest {
    private static final class MovableClock extends Clock {
        Instant now = Instant.parse("2026-11-21T12:00:00Z");

        @Override public ZoneOffset getZone() {
            return ZoneOffset.UTC;
        }

        @Override public Clock withZone(java.time.ZoneId zone) {
            return this;
        }

        @Override public Instant instant() {
            return now;
        }
    }

    @Test void admit_afterMaxFailures_refusesUntilTheWindowPasses() {
        MovableClock clock = new MovableClock();
        LoginThrottle t = new LoginThrottle(clock);
        for (int i = 0; i < LoginThrottle.MAX_FAILURES; i++) {
            assertThat(t.admit("10.0.0.1")).isZero();
        }

        assertThat(t.admit("10.0.0.1")).isEqualTo(LoginThrottle.WINDOW.toSeconds());
        assertThat(t.admit("10.0.0.2")).isZero();
        clock.now = clock.now.plus(LoginThrottle.WINDOW).plus(Duration.ofSeconds(1));
        assertThat(t.admit("10.0.0.1")).isZero();
    }

    @Test void succeeded_clearsTheCount() {
        LoginThrottle t = new LoginThrottle(new MovableClock());
        for (int i = 0; i < LoginThrottle.MAX_FAILURES - 1; i++) {
            t.admit("a");
        }

        t.succeeded("a");
        t.admit("a");

        assertThat(t.admit("a")).isZero();
    }
}
