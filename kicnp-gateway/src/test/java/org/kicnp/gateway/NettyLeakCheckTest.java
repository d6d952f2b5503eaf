package org.kicnp.gateway;

import static org.assertj.core.api.Assertions.assertThat;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufAllocator;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The leak check every test class of this module runs after it (NettyLeakCheck) sees a leak, and only a leak. */
class NettyLeakCheckTest {

    @Test
    void aBufferCollectedWithoutRelease_isReportedWithWhereItWasTouched() throws Exception {
        leakOne();

        assertThat(NettyLeakCheck.collectLeaks(1, 250))
                .singleElement().asString()
                .contains("ByteBuf leaked")
                .contains("leakOne"); // the records say where the buffer was made and written
    }

    @Test
    void buffersReleased_reportNothing() throws Exception {
        for (int i = 0; i < 100; i++) {
            ByteBuf b = ByteBufAllocator.DEFAULT.directBuffer(64);
            b.writeCharSequence("kept tidy", StandardCharsets.UTF_8);
            b.release();
        }

        assertThat(NettyLeakCheck.collectLeaks()).isEmpty();
    }

    private static void leakOne() {
        ByteBuf b = ByteBufAllocator.DEFAULT.directBuffer(64);
        b.writeCharSequence("never released", StandardCharsets.UTF_8);
        // no release: the buffer becomes garbage still holding its memory
    }
}
