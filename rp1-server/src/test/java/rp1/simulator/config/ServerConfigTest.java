package rp1.simulator.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;

import org.junit.jupiter.api.Test;

/** Server properties: the original's keys and defaults, the guide's aliases, our additions, clear errors. */
class ServerConfigTest {

    private static ServerConfig config(String text) throws ConfigException {
        return config(text, null);
    }

    private static ServerConfig config(String text, String plan) throws ConfigException {
        Properties p = new Properties();
        try {
            p.load(new StringReader(text));
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        return ServerConfig.from(p, "test.ini", plan);
    }

    @Test
    void defaultsAreTheOriginals() throws Exception {
        ServerConfig c = config("floorPlanFileName=WhiteRoom.txt\n");
        assertEquals(7758, c.port);
        assertEquals("127.0.0.1", c.bindAddress, "not on the network unless asked");
        assertTrue(c.enableGUI);
        assertTrue(c.enableNetworkClients);
        assertEquals(1.0, c.simulationSpeed);
        assertFalse(c.lockstep);
        assertEquals(0.05, c.modelingInterval, 1e-15);
        assertEquals(0.05, c.frameInterval, 1e-15);
        assertFalse(c.interlockEnabled);
        assertFalse(c.dlcEnabled);
        assertTrue(c.dlcSetIO);
        assertTrue(c.dlcSetLog);
        assertFalse(c.randomSeed.isPresent());
        assertTrue(c.noise.isOff(), "no noise unless asked");
    }

    @Test
    void noiseKeysSetEachFigureAndTheBearingIsInDegrees() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\nnoiseRangeSigma=0.02\nnoiseRangeDropout=0.1\n"
                + "noiseTargetRangeSigma=0.05\nnoiseTargetBearingSigma=3\nnoiseEncoderMiss=0.01\n"
                + "noiseSlipDistanceSigma=0.04\nnoiseSlipTurnSigma=0.08\n");
        assertEquals(0.02, c.noise.rangeSigma);
        assertEquals(0.1, c.noise.rangeDropout);
        assertEquals(0.05, c.noise.targetRangeSigma);
        assertEquals(Math.toRadians(3), c.noise.targetBearingSigma, 1e-15);
        assertEquals(0.01, c.noise.encoderMiss);
        assertEquals(0.04, c.noise.slipDistanceSigma);
        assertEquals(0.08, c.noise.slipTurnSigma);
        assertFalse(c.noise.isOff());
    }

    @Test
    void aNoiseProbabilityAboveOneOrANegativeSigmaIsRefusedByName() {
        ConfigException dropout = assertThrows(ConfigException.class,
                () -> config("floorPlanFileName=x\nnoiseRangeDropout=1.5\n"));
        assertTrue(dropout.getMessage().contains("noiseRangeDropout"), dropout.getMessage());
        ConfigException sigma = assertThrows(ConfigException.class,
                () -> config("floorPlanFileName=x\nnoiseSlipTurnSigma=-0.1\n"));
        assertTrue(sigma.getMessage().contains("noiseSlipTurnSigma"), sigma.getMessage());
    }

    @Test
    void theModellingRateIsRaisedToTheAnimationRateAndTheAnimationRateCappedAt32() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\nmodelingFrameRate=5\n");
        assertEquals(20.0, c.modelingFrameRate, "raised to the animation rate even without a GUI");
        ServerConfig fast = config("floorPlanFileName=x\nanimationFrameRate=100\nmodelingFrameRate=2000\n");
        assertEquals(32.0, fast.animationFrameRate);
        assertEquals(0.001, fast.modelingInterval, 1e-15, "never below a millisecond");
    }

    @Test
    void theGuidesSpellingsAreAccepted() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\nenableInterlock=true\ndlcSetLogger=false\n");
        assertTrue(c.interlockEnabled);
        assertFalse(c.dlcSetLog);
    }

    @Test
    void onlyTheFirstWordOfAValueCounts() throws Exception {
        assertFalse(config("floorPlanFileName=x\nenableGUI=false   # headless\n").enableGUI);
    }

    @Test
    void maxSpeedMeansLockstepAndNeedsTheInterlock() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\nsimulationSpeed=max\ninterlockEnabled=true\n");
        assertTrue(c.lockstep);
        ConfigException e = assertThrows(ConfigException.class, () -> config("floorPlanFileName=x\nsimulationSpeed=max\n"));
        assertTrue(e.getMessage().contains("needs interlockEnabled=true"), e.getMessage());
    }

    @Test
    void twoOutputsNamingOneFileAreRefused() throws Exception {
        // An event log named as the recording replaced it; a log named as the recording overwrote it.
        ConfigException e = assertThrows(ConfigException.class,
                () -> config("floorPlanFileName=x\nrecordFileName=run.rec\neventLogFileName=./run.rec\n"));
        assertEquals("test.ini: recordFileName and eventLogFileName name the same file, ./run.rec: each of the run's"
                + " outputs needs a file of its own", e.getMessage());
        assertThrows(ConfigException.class,
                () -> config("floorPlanFileName=x\nrecordFileName=out.log\nlogToFile=true\nlogFileName=out.log\n"));
        config("floorPlanFileName=x\nrecordFileName=out.log\nlogToFile=false\nlogFileName=out.log\n");
        config("floorPlanFileName=x\nrecordFileName=run.rec\neventLogFileName=events.txt\nsnapshotFileName=end.png\n");
    }

    @Test
    void badValuesNameTheFileTheKeyAndTheValue() {
        assertMessage("port=77x\n", "test.ini: port=77x: an integer expected");
        assertMessage("port=0\n", "test.ini: port=0: must be in [1, 65535]");
        assertMessage("port=65536\n", "test.ini: port=65536: must be in [1, 65535]");
        assertMessage("enableGUI=yes\n", "test.ini: enableGUI=yes: true or false expected");
        assertMessage("simulationSpeed=2000\n", "test.ini: simulationSpeed=2000: must be in [0.001, 1000.0]");
        assertMessage("simulationSpeed=fast\n", "test.ini: simulationSpeed=fast: a number expected");
        assertMessage("randomSeed=abc\n", "test.ini: randomSeed=abc: an integer expected");
    }

    @Test
    void everyPortOfTcpIsAcceptedNotOnly0_60sRange() throws Exception {
        assertEquals(40100, config("floorPlanFileName=x\nport=40100\n").port);
        assertEquals(80, config("floorPlanFileName=x\nport=80\n").port);
        assertEquals(65535, config("floorPlanFileName=x\nport=65535\n").port);
    }

    @Test
    void aMisspeltKeyIsRefusedWithTheNearestKnownOne() {
        assertMessage("simulationSpeed=max\ninterlockEnabled=true\nmaxSimulationTme=30\n",
                "test.ini: maxSimulationTme=30: unknown key; did you mean maxSimulationTime?");
        assertMessage("EnableGui=false\n", "did you mean enableGUI?");
    }

    @Test
    void anEmptyValueIsRefusedRatherThanTakenForTheDefault() {
        assertMessage("simulationSpeed=\n", "test.ini: simulationSpeed=: empty value");
        assertMessage("logVerbose =   \n", "test.ini: logVerbose=: empty value");
    }

    @Test
    void aKeyOf0_60ThatTheServerDoesNotUseIsAcceptedWithAWarning() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\nhostName=127.0.0.1\n");
        assertEquals(1, c.warnings.size(), c.warnings.toString());
        assertTrue(c.warnings.get(0).startsWith("test.ini: hostName=127.0.0.1: ignored (a client key"), c.warnings.get(0));
        assertTrue(config("floorPlanFileName=x\n").warnings.isEmpty());
    }

    @Test
    void aRecordingsPropertiesReplayEvenWithAKeyThisVersionDoesNotKnow() throws Exception {
        Properties p = new Properties();
        p.setProperty("floorPlanFileName", "x");
        p.setProperty("someOldKey", "1");
        ServerConfig c = ServerConfig.fromRecorded(p, "run.rec (its properties)");
        assertTrue(c.warnings.get(0).contains("someOldKey=1: unknown key"), c.warnings.toString());
    }

    @Test
    void aKeyReadButNotDeclaredInTheTableIsAProgrammingErrorNotASilentTypo() {
        Properties p = new Properties();
        p.setProperty("byteBudget", "10");
        PropertyReader r = new PropertyReader(p, "test.ini",
                new PropertyKeys(ServerConfig.KEYS, ServerConfig.UNUSED_0_60_KEYS, ServerConfig.KEY_FAMILIES));
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> r.string("byteBudget"));
        assertTrue(e.getMessage().contains("not declared in ServerConfig.KEYS"), e.getMessage());
    }

    @Test
    void aFamilyPrefixAcceptsEveryKeyUnderIt() throws Exception {
        PropertyKeys keys = new PropertyKeys(Set.of("port"), Map.of(), List.of("param."));
        assertTrue(keys.isKnown("param.speed"));
        assertFalse(keys.isKnown("params"));
        assertEquals("port", keys.nearest("prot"));
    }

    @Test
    void inconsistentSettingsAreRefused() {
        assertMessage("logToFile=true\n", "logToFile=true, but logFileName is missing");
        assertMessage("dlcEnabled=true\n", "dlcEnabled=true, but no class name is given in dlcName");
        assertMessage("dlcEnabled=true\ndlcName=a.B\ndlcSetIO=false\nenableNetworkClients=false\n",
                "enableNetworkClients=false");
    }

    @Test
    void waitForClientsIsOneByDefaultOnlyAtMaxSpeedWithNetworkClientsAndNoLoadedClient() throws Exception {
        String max = "floorPlanFileName=x\nsimulationSpeed=max\ninterlockEnabled=true\n";
        assertEquals(1, config(max).waitForClients);
        assertEquals(0, config("floorPlanFileName=x\n").waitForClients,
                "a paced clock: a client may ask for a timeout first");
        assertEquals(0, config(max + "dlcEnabled=true\ndlcName=a.B\n").waitForClients);
        assertEquals(0, config(max + "dlcEnabled=true\ndlcName=a.B\nenableNetworkClients=false\n").waitForClients);
        assertEquals(2, config(max + "dlcEnabled=true\ndlcName=a.B,c.D\nenableNetworkClients=false\nwaitForClients=2\n")
                .waitForClients);
    }

    @Test
    void aWaitForClientsThatCanNeverBeMetIsRefused() {
        assertMessage("enableNetworkClients=false\nwaitForClients=1\n", "waitForClients=1 can never be met: network "
                + "clients are disabled (enableNetworkClients=false) and no client is loaded (dlcName)");
        assertMessage("enableNetworkClients=false\ndlcEnabled=true\ndlcName=a.B\nwaitForClients=2\n",
                "waitForClients=2 can never be met: network clients are disabled (enableNetworkClients=false) and "
                        + "only 1 client is loaded (dlcName)");
    }

    @Test
    void theFloorPlanIsRequiredUnlessGivenOnTheCommandLine() throws Exception {
        ConfigException e = assertThrows(ConfigException.class, () -> config("port=7758\n"));
        assertTrue(e.getMessage().contains("the floor plan is missing"), e.getMessage());
        assertEquals("contest.txt", config("floorPlanFileName=x\n", "contest.txt").floorPlanFileName);
    }

    @Test
    void severalInProcessClientsMayBeNamed() throws Exception {
        ServerConfig c = config("floorPlanFileName=x\ndlcEnabled=true\ndlcName=a.One,b.Two\n");
        assertEquals(Arrays.asList("a.One", "b.Two"), c.dlcNames);
    }

    private static void assertMessage(String text, String expected) {
        ConfigException e = assertThrows(ConfigException.class, () -> config("floorPlanFileName=x\n" + text));
        assertTrue(e.getMessage().contains(expected), "expected '" + expected + "' in: " + e.getMessage());
    }

    @Test
    void commandLineFlagsNeedValuesAndTheLastOneWins() throws Exception {
        ServerArguments a = ServerArguments.parse(new String[] {"-p", "a.ini", "-f", "x.txt", "-p", "b.ini"});
        assertEquals("b.ini", a.propertiesName);
        assertEquals("x.txt", a.planName);
        ConfigException e = assertThrows(ConfigException.class, () -> ServerArguments.parse(new String[] {"-f"}));
        assertTrue(e.getMessage().startsWith("Missing specification for -f option"));
    }

    @Test
    void anUnknownOptionOrAStrayWordIsRefusedWithTheUsage() {
        ConfigException option = assertThrows(ConfigException.class, () -> ServerArguments.parse(new String[] {"-x"}));
        assertTrue(option.getMessage().startsWith("unknown option -x\nusage: java rp1.Server"), option.getMessage());
        ConfigException word = assertThrows(ConfigException.class,
                () -> ServerArguments.parse(new String[] {"-p", "a.ini", "clientzero.ini"}));
        assertTrue(word.getMessage().startsWith("unexpected argument clientzero.ini\nusage:"), word.getMessage());
    }

    @Test
    void portHeadlessAndClassPathAreTakenFromTheCommandLine() throws Exception {
        ServerArguments a = ServerArguments.parse(new String[] {"--port", "40100", "--headless", "-cp", "a" + java.io.File.pathSeparator
                + "b.jar", "--classpath", "c"});
        assertEquals(40100, a.port.getAsInt());
        assertTrue(a.headless);
        assertEquals(List.of("a", "b.jar", "c"), a.classPath);
        ServerArguments none = ServerArguments.parse(new String[0]);
        assertFalse(none.port.isPresent());
        assertFalse(none.headless);
        ConfigException e = assertThrows(ConfigException.class, () -> ServerArguments.parse(new String[] {"--port", "0"}));
        assertEquals("--port 0: a port number from 1 to 65535 expected", e.getMessage());
    }

    @Test
    void helpIsAskedForWithDashHOrDashDashHelp() throws Exception {
        assertTrue(ServerArguments.parse(new String[] {"-h"}).help);
        assertTrue(ServerArguments.parse(new String[] {"--help"}).help);
        assertFalse(ServerArguments.parse(new String[] {"-p", "a.ini"}).help);
    }

    @Test
    void paramKeysAreTheRobotsParametersByNameWhateverTheName() throws ConfigException {
        ServerConfig c = config("floorPlanFileName=WhiteRoom.txt\nparam.speed=0.3  # m/s\nparam.goal.x=2\n");
        assertEquals(Map.of("speed", "0.3", "goal.x", "2"), c.parameters);
        assertTrue(ServerConfig.isParameter("param.anything"));
        assertFalse(ServerConfig.isParameter("param."));
        assertEquals("test.ini: param.=1: a parameter needs a name after param.",
                assertThrows(ConfigException.class, () -> config("floorPlanFileName=WhiteRoom.txt\nparam.=1\n")).getMessage());
    }
}
