// A measuring aid, not project code: records episodes of the real Mario AI
// Benchmark 0.2.0 tick by tick so that `examples/replay_oracle.rs` can replay
// the same level and keys in our simulator and find the first tick where the
// two differ. It builds against the oracle's compiled classes
// (../shared/oracle/mario, `bash build.sh`); CI never needs it.
//
//   javac -d OUT -cp "BUILD/classes:SRC/lib/*" Trace.java
//   java -cp "OUT:BUILD/classes:SRC/lib/*" oracle.Trace --policy fwdjump|random --episodes N --seed S > trace.txt
//
// Episodes are drawn as the oracle's harness draws them (one java.util.Random(seed)
// for level seeds and start modes; the random policy from a second generator).
// Output, one record per line:
//   E <levelSeed> <startMode> <length> <height> <xExit> <yExit>
//   B <x> <y> <block> <data>            every non-empty cell of the fresh level
//   S <x> <y> <kind> <winged 0|1>       every sprite template
//   T <keys> <xbits> <ybits> <mode> <status> <bonus> <sprites> <s0> … <s26>   after each tick
//     keys: the keys of that tick (1 left, 2 right, 4 jump, 8 speed); x, y: Mario's
//     position as Float.floatToIntBits in hex (exact); bonus: getIntermediateReward();
//     sprites: sprites on the scene other than Mario; s0 … s26: the thesis's 27
//     variables as the oracle's State27 computes them (shoot as the API's).
package oracle;

import ch.idsia.agents.controllers.ForwardAgent;
import ch.idsia.benchmark.mario.engine.LevelScene;
import ch.idsia.benchmark.mario.engine.level.Level;
import ch.idsia.benchmark.mario.engine.level.SpriteTemplate;
import ch.idsia.benchmark.mario.engine.sprites.Mario;
import ch.idsia.benchmark.mario.environments.Environment;
import ch.idsia.benchmark.mario.environments.MarioEnvironment;
import ch.idsia.tools.MarioAIOptions;

import java.io.BufferedWriter;
import java.io.OutputStreamWriter;
import java.lang.reflect.Field;
import java.util.Random;

public final class Trace {
    public static void main(String[] args) throws Exception {
        String policy = "fwdjump";
        int episodes = 10;
        long seed = 1;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--policy": policy = args[++i]; break;
                case "--episodes": episodes = Integer.parseInt(args[++i]); break;
                case "--seed": seed = Long.parseLong(args[++i]); break;
                default: throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        MarioAIOptions options = new MarioAIOptions(new String[]{"-vis", "off", "-fps", "100",
            "-ld", "0", "-lt", "0", "-ll", "256", "-tl", "200", "-lhb", "off", "-rfw", "22", "-rfh", "22"});
        options.setAgent(new ForwardAgent());
        MarioEnvironment env = MarioEnvironment.getInstance();
        Field f = MarioEnvironment.class.getDeclaredField("levelScene");
        f.setAccessible(true);
        Random master = new Random(seed);
        Random actRng = new Random(seed * 7919 + 17);
        BufferedWriter out = new BufferedWriter(new OutputStreamWriter(System.out), 1 << 16);
        boolean[] keys = new boolean[Environment.numberOfKeys];
        for (int ep = 0; ep < episodes; ep++) {
            long levelSeed = master.nextInt(Integer.MAX_VALUE);
            int mode = master.nextInt(3);
            options.setLevelRandSeed((int) levelSeed);
            options.setMarioMode(mode);
            env.reset(options);
            LevelScene scene = (LevelScene) f.get(env);
            Level level = env.getLevel();
            out.write("E " + levelSeed + " " + mode + " " + level.length + " " + level.height + " "
                + level.xExit + " " + level.yExit + "\n");
            for (int x = 0; x < level.length; x++)
                for (int y = 0; y < level.height; y++) {
                    if (level.map[x][y] != 0 || level.data[x][y] != 0)
                        out.write("B " + x + " " + y + " " + (level.map[x][y] & 0xff) + " " + level.data[x][y] + "\n");
                    SpriteTemplate st = level.spriteTemplates[x][y];
                    if (st != null)
                        out.write("S " + x + " " + y + " " + st.getType() + "\n");
                }
            java.util.Arrays.fill(keys, false);
            State27 st = new State27();
            st.reset(env);
            while (!env.isLevelFinished()) {
                int k = (keys[Mario.KEY_LEFT] ? 1 : 0) | (keys[Mario.KEY_RIGHT] ? 2 : 0)
                    | (keys[Mario.KEY_JUMP] ? 4 : 0) | (keys[Mario.KEY_SPEED] ? 8 : 0);
                env.tick();
                float[] p = env.getMarioFloatPos();
                out.write("T " + k + " " + Integer.toHexString(Float.floatToIntBits(p[0])) + " "
                    + Integer.toHexString(Float.floatToIntBits(p[1])) + " " + env.getMarioMode() + " "
                    + env.getMarioStatus() + " " + env.getIntermediateReward() + " "
                    + (scene.sprites.size() - 1));
                if (System.getenv("TRACE_SPRITES") != null)
                    for (ch.idsia.benchmark.mario.engine.sprites.Sprite sp : scene.sprites)
                        out.write(" | " + sp.kind + " " + sp.x + " " + sp.y + " " + sp.mapX + " " + sp.mapY + " " + sp.isDead());
                st.observe(env);
                for (int v : st.s) out.write(" " + v);
                out.write("\n");
                // The policies of the oracle's harness (Oracle.policy), choosing the next tick's keys.
                java.util.Arrays.fill(keys, false);
                if (policy.equals("random")) {
                    int a = actRng.nextInt(12);
                    boolean[] b = ACTIONS[a];
                    System.arraycopy(b, 0, keys, 0, keys.length);
                } else {
                    keys[Mario.KEY_RIGHT] = true;
                    keys[Mario.KEY_SPEED] = true;
                    keys[Mario.KEY_JUMP] = env.isMarioAbleToJump() || !env.isMarioOnGround();
                }
                env.performAction(keys.clone());
            }
        }
        out.flush();
    }

    static final boolean[][] ACTIONS = new boolean[12][];
    static {
        int[][] k = { {}, {Mario.KEY_LEFT}, {Mario.KEY_RIGHT}, {Mario.KEY_JUMP}, {Mario.KEY_SPEED},
            {Mario.KEY_LEFT, Mario.KEY_JUMP}, {Mario.KEY_RIGHT, Mario.KEY_JUMP},
            {Mario.KEY_LEFT, Mario.KEY_SPEED}, {Mario.KEY_RIGHT, Mario.KEY_SPEED},
            {Mario.KEY_JUMP, Mario.KEY_SPEED}, {Mario.KEY_LEFT, Mario.KEY_JUMP, Mario.KEY_SPEED},
            {Mario.KEY_RIGHT, Mario.KEY_JUMP, Mario.KEY_SPEED} };
        for (int a = 0; a < 12; a++) {
            ACTIONS[a] = new boolean[Environment.numberOfKeys];
            for (int key : k[a]) ACTIONS[a][key] = true;
        }
    }
}
