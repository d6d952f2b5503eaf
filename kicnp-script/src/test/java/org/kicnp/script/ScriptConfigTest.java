package org.kicnp.script;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import java.util.Properties;

import org.junit.jupiter.api.Test;

class ScriptConfigTest {

    @Test
    void fromProperties_readsLimitsAndAllowList() {
        Properties properties = new Properties();
        properties.setProperty("script.time.limit.ms", "250");
        properties.setProperty("script.statement.limit", "5000");
        properties.setProperty("script.allow.classes", " java.lang.Math, java.time.LocalDate ,,");

        ScriptConfig config = ScriptConfig.fromProperties(properties);

        assertThat(config.timeLimit()).isEqualTo(Duration.ofMillis(250));
        assertThat(config.statementLimit()).isEqualTo(5000);
        assertThat(config.allowedHostClasses()).containsExactlyInAnyOrder("java.lang.Math", "java.time.LocalDate");
        assertThat(config.maxIdleContexts()).isEqualTo(ScriptConfig.defaults().maxIdleContexts());
    }

    @Test
    void fromProperties_whenEmpty_givesDefaults() {
        assertThat(ScriptConfig.fromProperties(new Properties())).isEqualTo(ScriptConfig.defaults());
        assertThat(ScriptConfig.defaults().allowedHostClasses()).isEmpty();
    }

    @Test
    void fromProperties_whenNotANumber_namesTheProperty() {
        Properties properties = new Properties();
        properties.setProperty("script.statement.limit", "lots");

        assertThatThrownBy(() -> ScriptConfig.fromProperties(properties))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("The property 'script.statement.limit' must be a whole number, not 'lots'.");
    }

    @Test
    void constructor_whenTimeLimitNotPositive_refuses() {
        assertThatThrownBy(() -> ScriptConfig.defaults().withTimeLimit(Duration.ZERO))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("The script time limit must be positive, not PT0S.");
    }
}
