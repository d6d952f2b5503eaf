package org.kicnp.robots;

import org.kicnp.core.Value;

import java.util.List;
import java.util.Objects;

/**
 * A sensor signal of one robot as the protocol's {@code sensor} message carries it: the sensor's name and its slot
 * values, the first being the one conditions usually test. The signals of the simulated robots:
 * <ul>
 *   <li>{@code face_seen} (Robovie): the recognised known user (the name of their {@code KnownUser} frame, whose
 *       {@code name} slot says what they are called) or {@code unknown}, the face descriptor (a list of
 *       floats), the distance in metres, the bearing in degrees, the camera track;</li>
 *   <li>{@code face_lost} (Robovie): that frame name or {@code unknown}, the track;</li>
 *   <li>{@code bumper} (Scout): pressed (boolean), the bumper number, what it touched ({@code ""} on release);</li>
 *   <li>{@code arrival}: the user approached or {@code point}, x, y, heading;</li>
 *   <li>{@code fall} (PINO): what it stumbled on;</li>
 *   <li>{@code utterance} (Robovie): the text spoken, its duration in seconds;</li>
 *   <li>{@code simulator}: {@code exited} and the reason, when the simulator died.</li>
 * </ul>
 */
public record SensorSignal(String sensor, List<Value> values) {
    public SensorSignal {
        Objects.requireNonNull(sensor, "sensor");
        values = List.copyOf(values);
    }

    public static SensorSignal of(String sensor, Value... values) {
        return new SensorSignal(sensor, List.of(values));
    }

    /** The first value, which the server also keeps as the signal frame's {@code value} slot. */
    public Value first() {
        return values.getFirst();
    }
}
