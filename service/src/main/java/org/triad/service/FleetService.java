package org.triad.service;

import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

import org.triad.building.Claims;
import org.triad.refarc.GoalPlanner;
import org.triad.refarc.Status;
import org.triad.refarc.fleet.FleetRobot;
import org.triad.refarc.fleet.FloorMap;
import org.triad.runtime.app.Failure;
import org.triad.runtime.app.GoalInstance;
import org.triad.runtime.app.State;
import org.triad.runtime.app.TaskInstance;
import org.triad.runtime.schema.GoalSolver;
import org.triad.runtime.schema.ModelTask;
import org.triad.service.TaskCatalog.TaskCall;
import org.triad.service.Views.EventView;
import org.triad.service.Views.LiveEvent;
import org.triad.service.Views.RequestView;
import org.triad.service.Views.RobotView;
import org.triad.service.Views.TaskView;
import org.triad.service.store.Records.EventRow;
import org.triad.service.store.Records.RequestRow;
import org.triad.service.store.Records.TaskRow;
import org.triad.service.store.DispatchLease;
import org.triad.service.store.StoreHealth;
import org.triad.service.store.TaskStore;
import org.triad.service.store.TaskState;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The task queue and the fleet: accepts tasks (stored before they are acknowledged), dispatches each
 * to the idle robot that can finish it soonest, records every Status event, raises a remote-operation
 * request when a robot aborts, and carries out the operator's decisions. The database is the truth;
 * the queue in memory is rebuilt from it at start, where a task that was running when the service
 * stopped is marked interrupted and queued again (RefArc then plans it from the robot's current state).
 */
public final class FleetService implements AutoCloseable {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** A robot on which this many tasks in a row aborted is taken out of dispatch until the operator puts it back. */
    public static final int ABORTS_IN_A_ROW = 3;
    /**
     * How many times a task that the building's congestion ended ({@link Failure.Cause#CONGESTION}: traffic control gave
     * up on a drive, a wait over its bound or a refusal to avoid a deadlock) is queued again before it ends aborted with
     * the reason. Each run already re-planned around the jam (RefArc's re-plans), so a task that congestion ends this many
     * times more stands in a jam that does not clear by itself (a robot lost in a corridor, a blocked lift): the operator
     * decides then. Such aborts never count toward {@link #ABORTS_IN_A_ROW}: a jam would take every healthy robot in it out
     * of dispatch (service/BENCHMARK.md, the mixed benchmark under traffic control).
     */
    public static final int CONGESTION_REQUEUES = 3;
    /**
     * How the reason of a task that the planner proved impossible from the observed state ({@link Failure.Cause#REFUSED}: a
     * battery too low for the trip, an item nowhere) begins. The task ends aborted, so that the operator can retry it once the
     * state has changed (the robot charged, the item brought), mark it done or cancel it; the robot is not held to account
     * for it ({@link #ABORTS_IN_A_ROW}).
     */
    public static final String REFUSED = "refused: ";
    /** How long a task queued again after congestion waits before its next run, times the how-manieth time it is (the others move on meanwhile). */
    private volatile java.time.Duration congestionPause = java.time.Duration.ofSeconds(10);
    /** Tasks queued again after congestion, with when they may run again. */
    private final Map<Long, Instant> notBefore = new ConcurrentHashMap<>();
    /**
     * Robots whose last runs congestion ended, with until when they rest, and how many such runs in a row: a robot that
     * stands in a jam and takes the next task at once meets the same refusal within a second (RefArc's re-plans too) and
     * burns through the queue (the mixed benchmark: one courier shut in the storage room ended a task every few seconds).
     */
    private final Map<String, Instant> resting = new ConcurrentHashMap<>();
    private final Map<String, Integer> jammedInARow = new ConcurrentHashMap<>();
    /** At most this many pauses a robot rests after congestion ended its runs in a row. */
    private static final int MAX_REST_PAUSES = 6;

    private final TaskCatalog catalog;
    private final TaskStore store;
    private final GoalSolver estimator;
    private final Clock clock;
    /** The robots by name, in fleet order; replaced as a whole when a robot joins (readers take the map they find). */
    private volatile Map<String, RobotLane> lanes = Map.of();
    /** Robots that announced themselves and cannot be used, with the reason (shown to the operator). */
    private final Map<String, String> refusedRobots = java.util.Collections.synchronizedMap(new LinkedHashMap<>());
    private final GoalPlanner goalPlanner;
    /** The charging policy (application.properties), or null; its task checked against the models. */
    private volatile ChargingPolicy charging;
    private volatile TaskCall chargingCall;
    /** Robots low on battery that were sent to charge, with the charging task: one task per time below the threshold. */
    private final Map<String, Long> sentToCharge = new ConcurrentHashMap<>();
    /**
     * Tasks stopped because their robot ran low while it worked, with that robot: queued again for it (it may carry their
     * objects), to run once it has charged; any robot takes them when it leaves dispatch or cannot charge.
     */
    private final Map<Long, String> chargingStopped = new ConcurrentHashMap<>();
    /** How a stop for charging begins ({@link RobotLane#stop}): the task is queued again for its robot, its objects kept. */
    private static final String CHARGING_STOP = "stopped to charge first: ";
    private final List<Consumer<LiveEvent>> listeners = new CopyOnWriteArrayList<>();
    private final Object lock = new Object();
    private final Map<Long, Integer> priorities = new ConcurrentHashMap<>();
    /**
     * Queued task ids in dispatch order: higher priority first, then submission order (a retried task
     * keeps its place). A task's priority is put in {@code priorities} before it joins.
     */
    private final TreeSet<Long> queue = new TreeSet<>(
            java.util.Comparator.comparingInt((Long id) -> -priorities.getOrDefault(id, 0)).thenComparing(id -> id));
    private final Map<Long, String> preferred = new ConcurrentHashMap<>();
    /** The checked submissions of tasks not yet finished, read by request threads for their descriptions. */
    private final Map<Long, TaskCall> calls = new ConcurrentHashMap<>();
    /** Which running task holds which objects: a task waits while another holds an object it names. */
    private final Claims claims;
    /** The objects each queued or running task claims. */
    private final Map<Long, Set<String>> claimed = new ConcurrentHashMap<>();
    /** Queued tasks that waited for an object, with the holder they waited for last. */
    private final Map<Long, Claims.Holder> waitedFor = new ConcurrentHashMap<>();
    private final List<Long> refusedToPublish = new CopyOnWriteArrayList<>();
    /** When each running task was dispatched, and how long the last completed tasks took: for the expected start and finish. */
    private final Map<Long, Instant> dispatchedAt = new ConcurrentHashMap<>();
    private final java.util.ArrayDeque<java.time.Duration> durations = new java.util.ArrayDeque<>();
    private final Thread dispatcher;
    private volatile boolean running = true;
    private volatile long dispatchNanos;
    private volatile long dispatches;
    private final DispatchLease lease;
    /** Whether this instance dispatches (holds the lease); on the embedded database always. */
    private volatile boolean dispatching;
    /** Take-overs and losses of the dispatch lease, newest first, for the operator page. */
    private final List<String> leaseHistory = new CopyOnWriteArrayList<>();
    private long lastSync;

    public FleetService(TaskCatalog catalog, TaskStore store, List<FleetRobot> robots, GoalSolver planner, Clock clock) {
        this(catalog, store, robots, planner, clock, DispatchLease.of(store.database()));
    }

    /**
     * @param lease which instance dispatches: only the holder dispatches and re-queues running tasks
     *              at take-over; every instance accepts and serves tasks
     */
    public FleetService(TaskCatalog catalog, TaskStore store, List<FleetRobot> robots, GoalSolver planner, Clock clock, DispatchLease lease) {
        this.catalog = catalog;
        this.store = store;
        this.estimator = planner;
        this.clock = clock;
        this.lease = lease;
        this.claims = new Claims(catalog.schema());
        this.goalPlanner = new org.triad.refarc.model.SchemaGoalPlanner(planner);
        Map<String, RobotLane> first = new LinkedHashMap<>();
        for (FleetRobot r : robots) {
            first.put(r.name(), new RobotLane(r, goalPlanner, this::onStatus));
        }
        lanes = java.util.Collections.unmodifiableMap(first);
        if (lease.holds()) {
            synchronized (lock) {
                recover();
                dispatching = true;
            }
            if (store.database().shared()) {
                note("this instance dispatches (it took the lease at start)");
            }
        } else {
            note("another instance dispatches; this one serves the API and takes over if that one stops");
        }
        dispatcher = new Thread(this::dispatchLoop, "triad-dispatcher");
        dispatcher.setDaemon(true);
        dispatcher.start();
        Thread poses = new Thread(this::publishPoses, "triad-positions");
        poses.setDaemon(true);
        poses.start();
    }

    private void note(String what) {
        leaseHistory.add(0, clock.instant() + " " + what);
        while (leaseHistory.size() > 20) {
            leaseHistory.remove(leaseHistory.size() - 1);
        }
        if (store.database().shared()) {
            System.err.println("triad serve: " + what);
        }
    }

    /**
     * Tasks that were running when the service (or the instance that dispatched) stopped are
     * interrupted and queued again; queued ones stay queued. Returns how many were interrupted.
     */
    private int recover() {
        Instant now = clock.instant();
        queue.clear();
        preferred.clear();
        List<TaskRow> interrupted = store.tasksInOrder(TaskState.RUNNING);
        for (TaskRow t : interrupted) {
            store.insertEvent(t.id(), "interrupted", t.robot(), "interrupted: the service stopped while robot " + t.robot()
                    + " ran the task; queued again, to be re-planned from the robot's current state", now);
            store.updateTask(t.id(), TaskState.QUEUED, null, null, "interrupted by a service restart", now);
        }
        for (TaskRow t : store.tasksInOrder(TaskState.QUEUED)) {
            calls.remove(t.id()); // checked afresh against the models of this start
            enqueueStored(t, now);
        }
        lastSync = System.nanoTime();
        return interrupted.size();
    }

    /**
     * Puts a task queued in the database into the queue in memory (its priority first: the queue orders
     * by it); a task that no longer fits the models is aborted with the reason. Call with the lock held.
     */
    private void enqueueStored(TaskRow t, Instant now) {
        try {
            calls.computeIfAbsent(t.id(), id -> catalog.check(request(t)));
            priorities.put(t.id(), t.priority());
            queue.add(t.id());
            if (t.preferredRobot() != null) {
                preferred.put(t.id(), t.preferredRobot());
            }
        } catch (ServiceError e) {
            if (e.code().equals("database-unavailable")) {
                throw e;
            }
            abort(t.id(), null, null, "the task no longer fits the models or the world: " + e.getMessage(), now);
        }
    }

    /**
     * Brings the queue in memory in line with the database: tasks queued through another instance or
     * left out after a failed write join it, tasks finished elsewhere leave it, and a cancel asked of
     * another instance stops the robot that runs the task here.
     */
    private void sync() {
        Instant now = clock.instant();
        java.util.Set<Long> queued = new java.util.HashSet<>();
        for (TaskRow t : store.tasksInOrder(TaskState.QUEUED)) {
            queued.add(t.id());
            if (!queue.contains(t.id())) {
                enqueueStored(t, now);
            }
        }
        queue.removeIf(id -> !queued.contains(id));
        for (TaskRow t : store.tasksInOrder(TaskState.RUNNING)) {
            RobotLane lane = t.robot() == null ? null : lanes.get(t.robot());
            if (lane != null && t.reason() != null && t.reason().startsWith(CANCEL_REQUESTED) && lane.currentTask().orElse(-1L) == t.id()) {
                lane.stop("cancelled by " + t.reason().substring(CANCEL_REQUESTED.length()));
            }
        }
        lastSync = System.nanoTime();
    }

    private static final String CANCEL_REQUESTED = "cancel requested by ";
    private static final String LEASE_LOST = "this service instance lost the dispatch lease (its database connection); another instance re-plans the task";

    private static JsonNode request(TaskRow t) {
        try {
            return JSON.createObjectNode().put("task", t.task()).set("args", JSON.readTree(t.args()));
        } catch (JsonProcessingException e) {
            throw new ServiceError(500, "corrupt-task", "task " + t.id() + " has unreadable arguments");
        }
    }

    public TaskCatalog catalog() {
        return catalog;
    }

    public void addListener(Consumer<LiveEvent> listener) {
        listeners.add(listener);
    }

    public void removeListener(Consumer<LiveEvent> listener) {
        listeners.remove(listener);
    }

    // ---- staff --------------------------------------------------------------------------------

    public TaskView submit(JsonNode body) {
        return submit(body, null).task();
    }

    /** A submission's answer: the task, and whether it was stored now (201) or before under the same key (200). */
    public record Submission(TaskView task, boolean created) {
    }

    /**
     * Stores and queues a task. With an idempotency {@code key} a repeated submission (a client that
     * lost the answer, e.g. to a crash after the commit) gets the task stored before, if it is the same task.
     */
    public Submission submit(JsonNode body, String key) {
        TaskCall call = catalog.check(body);
        // as precise as every database keeps it, so that the 201 and a later GET agree
        Instant now = clock.instant().truncatedTo(java.time.temporal.ChronoUnit.MILLIS);
        TaskStore.Submitted stored;
        synchronized (lock) {
            stored = store.submitTask(call.task(), call.args().toString(), call.priority(), now, "submitted: " + call.describe()
                    + (call.priority() == 0 ? "" : " with priority " + call.priority()), key);
            if (!stored.created()) {
                TaskRow t = stored.task();
                if (!t.task().equals(call.task()) || !t.args().equals(call.args().toString())) {
                    throw new ServiceError(422, "idempotency-key-reused", "the Idempotency-Key '" + key + "' was used for task " + t.id() + ", "
                            + callText(t) + "; a new task needs a new key");
                }
                return new Submission(view(t, true), false);
            }
            calls.put(stored.task().id(), call);
            priorities.put(stored.task().id(), call.priority());
            queue.add(stored.task().id());
            lock.notifyAll();
        }
        // the answer is built from what was written, without reading it back: one commit per submission
        TaskView v = view(stored.task(), List.of(view(stored.event())), forecast());
        if (!listeners.isEmpty()) {
            Map<String, Object> data = new LinkedHashMap<>();
            data.put("task", withoutEvents(v));
            data.put("event", view(stored.event()));
            publish(new LiveEvent("task", data));
        }
        return new Submission(v, true);
    }

    public Optional<TaskView> task(long id) {
        return store.task(id).map(t -> view(t, true));
    }

    public List<TaskView> tasks(TaskState state, int limit) {
        Map<Long, Instant[]> forecast = forecast();
        return store.tasks(state, limit).stream().map(t -> view(t, null, forecast)).toList();
    }

    /** Cancels a queued or aborted task at once, a running one at its robot's next step. */
    public TaskView cancel(long id, String who) {
        Instant now = clock.instant();
        synchronized (lock) {
            TaskRow t = require(id);
            switch (t.state()) {
                case QUEUED, ABORTED -> {
                    queue.remove(id);
                    preferred.remove(id);
                    waitedFor.remove(id);
                    notBefore.remove(id);
                    claims.release(id); // a task queued again after congestion kept what it held
                    store.resolveRequests(id, "cancelled", now);
                    store.insertEvent(id, "cancelled", t.robot(), "cancelled by " + who, now);
                    store.updateTask(id, TaskState.CANCELLED, t.robot(), null, "cancelled by " + who, now);
                }
                case RUNNING -> {
                    RobotLane lane = lanes.get(t.robot());
                    store.insertEvent(id, "cancelling", t.robot(), "cancel requested by " + who + "; the robot stops at its next step", now);
                    if (lane != null && lane.currentTask().orElse(-1L) == id) {
                        lane.stop("cancelled by " + who);
                    } else {
                        // the robot belongs to the instance that dispatches: it reads this at its next look at the database
                        store.updateTaskIf(id, TaskState.RUNNING, t.robot(), TaskState.RUNNING, t.robot(), CANCEL_REQUESTED + who, now);
                    }
                }
                default -> throw new ServiceError(409, "task-finished", "task " + id + " is " + t.state().json() + "; only queued, running or aborted tasks can be cancelled");
            }
        }
        publishRequests();
        return publishTask(id, true);
    }

    // ---- operator -----------------------------------------------------------------------------

    public TaskView retry(long id) {
        TaskRow t = require(id);
        if (t.state() != TaskState.ABORTED) {
            throw new ServiceError(409, "not-aborted", "task " + id + " is " + t.state().json() + "; only an aborted task can be retried");
        }
        String robot = t.robot() != null && lanes.containsKey(t.robot()) && lanes.get(t.robot()).online() ? t.robot() : null;
        return requeue(t, robot, "retried", "retried by the operator" + (robot == null ? "" : " on " + robot));
    }

    public TaskView reassign(long id, String robot) {
        TaskRow t = require(id);
        if (t.state() != TaskState.ABORTED && t.state() != TaskState.QUEUED) {
            throw new ServiceError(409, "not-reassignable", "task " + id + " is " + t.state().json() + "; only an aborted or queued task can be re-assigned");
        }
        if (robot != null) {
            RobotLane lane = lanes.get(robot);
            if (lane == null) {
                throw new ServiceError(422, "unknown-robot", "no robot '" + robot + "'; the fleet has " + lanes.keySet());
            }
            if (!lane.online()) {
                throw new ServiceError(409, "robot-offline", "robot " + robot + " is offline");
            }
        }
        return requeue(t, robot, "reassigned", "re-assigned by the operator to " + (robot == null ? "any robot" : robot));
    }

    private TaskView requeue(TaskRow t, String robot, String kind, String text) {
        Instant now = clock.instant();
        synchronized (lock) {
            TaskRow fresh = require(t.id());
            if (fresh.state() != t.state()) {
                throw new ServiceError(409, "changed", "task " + t.id() + " changed meanwhile; it is " + fresh.state().json());
            }
            TaskCall call = calls.computeIfAbsent(t.id(), id -> catalog.check(request(t)));
            calls.put(t.id(), call);
            store.resolveRequests(t.id(), kind, now);
            store.insertEvent(t.id(), kind, robot, text, now);
            store.updateTask(t.id(), TaskState.QUEUED, null, robot, null, now);
            notBefore.remove(t.id()); // the operator's word: now
            priorities.putIfAbsent(t.id(), t.priority());
            queue.add(t.id());
            if (robot == null) {
                preferred.remove(t.id());
            } else {
                preferred.put(t.id(), robot);
            }
            lock.notifyAll();
        }
        publishRequests();
        return publishTask(t.id(), true);
    }

    public TaskView markDone(long id) {
        Instant now = clock.instant();
        synchronized (lock) {
            TaskRow t = require(id);
            if (t.state() != TaskState.ABORTED) {
                throw new ServiceError(409, "not-aborted", "task " + id + " is " + t.state().json() + "; only an aborted task can be marked done");
            }
            store.resolveRequests(id, "done", now);
            store.insertEvent(id, "done", t.robot(), "marked done by hand by the operator", now);
            store.updateTask(id, TaskState.DONE, t.robot(), null, "done by hand", now);
        }
        publishRequests();
        return publishTask(id, true);
    }

    public List<RobotView> robots() {
        List<RobotView> out = new ArrayList<>(lanes.values().stream().map(this::view).toList());
        Map<String, String> refused;
        synchronized (refusedRobots) {
            refused = new LinkedHashMap<>(refusedRobots);
        }
        refused.forEach((name, why) -> out.add(refusedView(name, why)));
        return out;
    }

    private static RobotView refusedView(String name, String why) {
        return new RobotView(name, false, null, null, List.of(), 0, false, "refused: " + why, "refused", null, null, null);
    }

    /** The building's map: every robot where its platform reports it, on the layout the first robot with a floor map draws. */
    public Views.BuildingView building() {
        List<RobotView> robots = robots();
        for (RobotLane l : lanes.values()) {
            Optional<FloorMap> floor;
            try {
                floor = l.robot().floor();
            } catch (RuntimeException e) {
                continue;
            }
            if (floor.isPresent()) {
                org.triad.refarc.fleet.Pose p = quietly(l.robot()::pose);
                String layoutMap = p == null ? null : p.mapId();
                Map<String, FloorMap> floors = new java.util.LinkedHashMap<>();
                Map<String, FloorMap> each;
                try {
                    each = l.robot().floors();
                } catch (RuntimeException e) {
                    each = null; // drawn as one map below
                }
                if (each != null && !each.isEmpty()) {
                    each.forEach((id, f) -> floors.put(id, withoutRobots(f)));
                } else {
                    floors.put(layoutMap == null ? "" : layoutMap, withoutRobots(floor.get()));
                }
                FloorMap layout = floors.getOrDefault(layoutMap == null ? "" : layoutMap, withoutRobots(floor.get()));
                return new Views.BuildingView(robots, layout, layoutMap, floors);
            }
        }
        return new Views.BuildingView(robots, null, null, Map.of());
    }

    /** A floor's layout for the building's map: the robots come from their poses, not from one robot's picture. */
    private static FloorMap withoutRobots(FloorMap f) {
        return new FloorMap(f.time(), f.bounds(), f.areas(), f.walls(), f.doors(), f.waypoints(), List.of(), f.items(), f.people());
    }

    /**
     * Publishes the robots (positions, batteries, presence) on the event stream as {@code building}, every
     * {@value #POSES_MILLIS} ms while someone listens and something changed: the operator's live map.
     */
    private void publishPoses() {
        List<RobotView> last = null;
        while (running) {
            sleepQuietly(POSES_MILLIS);
            if (listeners.isEmpty()) {
                last = null;
                continue;
            }
            try {
                List<RobotView> now = robots();
                if (!now.equals(last)) {
                    publish(new LiveEvent("building", now));
                    last = now;
                }
            } catch (RuntimeException e) {
                // a platform that fails to report is shown without a position; the next round tries again
            }
        }
    }

    static final long POSES_MILLIS = 500;

    // ---- battery ------------------------------------------------------------------------------

    /**
     * From now on a robot reporting a charge below {@code policy.below()} gets no new task, and, if the policy
     * names a charging task, that task is queued for it (priority 100) once each time it falls below.
     *
     * @throws ServiceError when the charging task does not fit the models (its message names what)
     */
    public void useCharging(ChargingPolicy policy) {
        TaskCall call = policy.task() == null ? null : catalog.check(policy.task());
        synchronized (lock) {
            charging = policy;
            chargingCall = call;
            lock.notifyAll();
        }
    }

    /** The most robots running a task at once ({@link DispatchLimit}), or 0 for no limit. */
    private volatile int atOnce;

    /**
     * From now on at most {@code limit.robots()} robots run a task at the same time (a charging task is not held back);
     * the other idle robots wait where they stand, parked, until one of the working robots is done.
     */
    public void limitAtOnce(DispatchLimit limit) {
        synchronized (lock) {
            atOnce = limit.robots();
            lock.notifyAll();
        }
    }

    /** The robot's charge when the policy says it is too low for work, else null. */
    private Double lowCharge(RobotLane l) {
        ChargingPolicy policy = charging;
        if (policy == null) {
            return null;
        }
        org.triad.refarc.fleet.Battery b = quietly(l.robot()::battery);
        return b != null && b.charge() < policy.below() ? b.charge() : null;
    }

    /** Whether the queued task is the charging task for the robot it is bound to. */
    private boolean chargingTask(long id) {
        TaskCall c = chargingCall;
        TaskCall call = calls.get(id);
        return c != null && call != null && preferred.containsKey(id) && call.task().equals(c.task()) && call.args().equals(c.args());
    }

    /**
     * Queues the charging task for each online robot that fell below the threshold and stops the task such a robot runs,
     * at its next step (queued again for it; see {@link #chargingStopped}): a robot that went on working below the threshold
     * in a jammed task drained its battery on refused drives and steps aside, arrived idle with less than its charging
     * task needs (refused: the models keep a reserve), and stood for good where its task left it, often on a corridor node
     * in the others' way (the service's mixed benchmark: a courier at 0 %, BATTERY_EMPTY, holding a ring node). Call
     * with the lock held.
     */
    private void sendToCharge(List<Long> published) {
        ChargingPolicy policy = charging;
        if (policy == null) {
            return;
        }
        for (RobotLane l : lanes.values()) {
            Double low = lowCharge(l);
            if (low == null) {
                sentToCharge.remove(l.name());
                continue;
            }
            if (chargingCall == null || !l.online()) {
                continue;
            }
            Long sent = sentToCharge.get(l.name());
            Optional<Long> running = l.currentTask();
            if (sent != null && running.isPresent() && !running.get().equals(sent) && l.stopReason().isEmpty() && low < policy.stopBelow()) {
                String why = String.format(java.util.Locale.ROOT, "%srobot %s reports %.0f %% battery, below %.0f %%, while it works; queued again for it (task %d charges it)",
                        CHARGING_STOP, l.name(), low, policy.stopBelow(), sent);
                l.stop(why);
                System.err.println("triad serve: task " + running.get() + ": " + why);
            }
            if (sent != null || queue.stream().anyMatch(id -> l.name().equals(preferred.get(id)) && chargingTask(id))) {
                continue;
            }
            Instant now = clock.instant();
            String text = String.format(java.util.Locale.ROOT, "submitted by the service: robot %s reports %.0f %% battery, below %.0f %%; sent to charge: %s",
                    l.name(), low, policy.below(), chargingCall.describe());
            TaskStore.Submitted stored = store.submitTask(chargingCall.task(), chargingCall.args().toString(), 100, now, text, null);
            long id = stored.task().id();
            store.updateTask(id, TaskState.QUEUED, null, l.name(), null, now);
            calls.put(id, chargingCall);
            priorities.put(id, 100);
            preferred.put(id, l.name());
            queue.add(id);
            sentToCharge.put(l.name(), id);
            published.add(id);
            System.err.println("triad serve: " + text + " (task " + id + ")");
        }
    }

    /** Why a robot gets no new task for its battery, for the operator, or null. */
    private String batteryNote(RobotLane l) {
        Double low = lowCharge(l);
        ChargingPolicy policy = charging;
        if (low == null || policy == null) {
            return null;
        }
        Long sent = sentToCharge.get(l.name());
        return String.format(java.util.Locale.ROOT, "battery %.0f %% is below %.0f %%: no new task", low, policy.below())
                + (sent != null ? "; sent to charge (task " + sent + ")" : chargingCall == null ? "; no charging task is configured" : "");
    }

    // ---- robots that come and go (FleetChanges, through TriadService) ----------------------------

    /** Whether the fleet has a robot of this name (one that left included). */
    public boolean hasRobot(String name) {
        return lanes.containsKey(name);
    }

    /**
     * A robot that came while the service runs gets a lane of its own and is dispatched to from now on;
     * for a robot of the fleet that left, this says it is back.
     */
    public void join(FleetRobot robot) {
        RobotLane lane;
        boolean back;
        synchronized (lock) {
            if (!running) {
                return;
            }
            refusedRobots.remove(robot.name());
            lane = lanes.get(robot.name());
            back = lane != null;
            if (lane == null) {
                lane = new RobotLane(robot, goalPlanner, this::onStatus);
                Map<String, RobotLane> more = new LinkedHashMap<>(lanes);
                more.put(robot.name(), lane);
                lanes = java.util.Collections.unmodifiableMap(more);
            } else {
                lane.back();
            }
            lock.notifyAll();
        }
        System.err.println("triad serve: robot " + robot.name() + (back ? " is back" : " joined the fleet"));
        publish(new LiveEvent("robot", view(lane)));
    }

    /**
     * The platform reports a robot gone for {@code reason} (the true cause): it gets no task until it is
     * back, and the task it runs is stopped at its next step and ends aborted with that cause and a
     * remote-operation request (the robot may still hold what the task took, so the operator decides).
     */
    public void leave(String name, String reason) {
        RobotLane lane = lanes.get(name);
        if (lane == null) {
            return;
        }
        synchronized (lock) {
            lane.gone(reason);
            lane.stopAborting("robot " + name + " is gone: " + reason);
        }
        System.err.println("triad serve: robot " + name + " is gone: " + reason);
        publish(new LiveEvent("robot", view(lane)));
    }

    /** Something announced itself as a robot and cannot be used, for {@code reason}: shown to the operator, never dispatched to. */
    public void refuseRobot(String name, String reason) {
        if (lanes.containsKey(name)) {
            leave(name, "refused: " + reason);
            return;
        }
        refusedRobots.put(name, reason);
        System.err.println("triad serve: robot " + name + " refused: " + reason);
        publish(new LiveEvent("robot", refusedView(name, reason)));
    }


    public Optional<FloorMap> floor(String robot) {
        RobotLane lane = lanes.get(robot);
        if (lane == null) {
            throw new ServiceError(404, "not-found", "no robot '" + robot + "'; the fleet has " + lanes.keySet());
        }
        return lane.robot().floor();
    }

    /** Takes a robot out of dispatch (its running task is interrupted and queued again) or puts it back. */
    public RobotView setOnline(String robot, boolean online) {
        RobotLane lane = lanes.get(robot);
        if (lane == null) {
            throw new ServiceError(404, "not-found", "no robot '" + robot + "'; the fleet has " + lanes.keySet());
        }
        synchronized (lock) {
            if (online && lane.isGone()) {
                throw new ServiceError(409, "robot-gone", "robot " + robot + " is " + lane.offlineReason() + "; it comes back when its platform reports it again");
            }
            lane.setOnline(online);
            if (!online) {
                lane.stop("robot " + robot + " taken offline by the operator");
            }
            lock.notifyAll();
        }
        RobotView v = view(lane);
        publish(new LiveEvent("robot", v));
        return v;
    }

    public List<RequestView> requests(boolean all) {
        List<RequestView> out = new ArrayList<>();
        for (RequestRow r : store.requests(all)) {
            String call = Optional.ofNullable(calls.get(r.taskId())).map(TaskCall::describe)
                    .orElseGet(() -> store.task(r.taskId()).map(FleetService::callText).orElse("?"));
            out.add(new RequestView(r.id(), r.taskId(), call, r.robot(), r.goal(), r.reason(), Views.time(r.raisedAt()), Views.time(r.resolvedAt()),
                    r.resolution()));
        }
        return out;
    }

    /** The time each dispatch took to choose a robot (estimates included), ns, in order (the first 100,000): for benchmarks. */
    public List<Long> dispatchTimes() {
        synchronized (lock) {
            return List.copyOf(dispatchTimes);
        }
    }

    private final List<Long> dispatchTimes = new ArrayList<>();

    /** Mean time the dispatcher took to choose a robot (estimates included), ns, and how many dispatches. */
    public long[] dispatchStatistics() {
        return new long[] { dispatches == 0 ? 0 : dispatchNanos / dispatches, dispatches };
    }

    // ---- dispatch -----------------------------------------------------------------------------

    private record Choice(long task, TaskCall call, List<RobotLane> candidates) {
    }

    private void dispatchLoop() {
        Backoff backoff = new Backoff();
        while (running) {
            Choice choice;
            List<Long> nowWaiting = new ArrayList<>();
            try {
                if (!leaseHeld()) {
                    sleepQuietly(DispatchLease.POLL_MILLIS);
                    continue;
                }
                synchronized (lock) {
                    if (System.nanoTime() - lastSync > DispatchLease.POLL_MILLIS * 1_000_000L) {
                        sync();
                    }
                    choice = next(nowWaiting);
                    if (choice == null && nowWaiting.isEmpty()) {
                        backoff.reset();
                        try {
                            lock.wait(DispatchLease.POLL_MILLIS);
                        } catch (InterruptedException e) {
                            return;
                        }
                        continue;
                    }
                }
            } catch (ServiceError e) {
                // the database failed: everything stays in the database; try again after a pause
                sleepQuietly(backoff.next());
                continue;
            }
            long start = System.nanoTime();
            try {
                nowWaiting.forEach(id -> publishTask(id, false));
                if (choice == null) {
                    continue;
                }
                dispatch(choice, start);
                backoff.reset();
                for (Long refused : refusedToPublish) {
                    refusedToPublish.remove(refused);
                    publishTask(refused, false);
                }
            } catch (ServiceError e) {
                // the database failed: the task stays queued in the database and is tried again
                sleepQuietly(backoff.next());
            } catch (RuntimeException e) {
                if (choice == null) {
                    // publishing a wait failed: the task keeps waiting and is published with its next change
                    System.err.println("triad serve: dispatch: " + e);
                    continue;
                }
                synchronized (lock) {
                    queue.remove(choice.task());
                    abort(choice.task(), null, null, "the service could not dispatch the task: " + e, clock.instant());
                }
                publishRequests();
            }
        }
    }

    /**
     * Whether this instance dispatches now. Taking the lease over re-queues the tasks the previous
     * holder ran; losing it stops this instance's robots, whose tasks the new holder re-queues.
     */
    private boolean leaseHeld() {
        boolean holds = lease.holds();
        if (holds && !dispatching) {
            int interrupted;
            synchronized (lock) {
                interrupted = recover();
                dispatching = true;
            }
            note("this instance took over dispatch; " + interrupted + " task(s) the previous one ran are queued again");
        } else if (!holds && dispatching) {
            dispatching = false;
            synchronized (lock) {
                queue.clear();
                for (RobotLane l : lanes.values()) {
                    l.stop(LEASE_LOST);
                }
            }
            note("this instance lost the dispatch lease; its robots stop and another instance takes over");
        }
        return holds;
    }

    /** Pauses between attempts after a database failure: 250 ms, doubling to 5 s. */
    private static final class Backoff {
        private long next = 250;

        long next() {
            long now = next;
            next = Math.min(5000, next * 2);
            return now;
        }

        void reset() {
            next = 250;
        }
    }

    /**
     * Runs a write of a robot's report until the database takes it (or the service stops): the robot
     * waits meanwhile, and resumes when the full disk has room again or the connection is back.
     */
    private <T> T durably(java.util.function.Supplier<T> write) {
        Backoff backoff = new Backoff();
        while (true) {
            try {
                return write.get();
            } catch (ServiceError e) {
                if (!running || !dispatching || !e.code().equals("database-unavailable")) {
                    throw e;
                }
                sleepQuietly(backoff.next());
            }
        }
    }

    /**
     * The first queued task (in dispatch order) some idle online robot may take, with those robots. A task
     * one of whose objects another running task holds waits (it keeps its place; later tasks may go
     * first); its reason says for what, and is recorded once per holder in {@code nowWaiting}.
     */
    private Choice next(List<Long> nowWaiting) {
        sendToCharge(nowWaiting);
        Instant restNow = clock.instant();
        List<RobotLane> idle = lanes.values().stream().filter(l -> l.online() && l.idle())
                .filter(l -> !resting.getOrDefault(l.name(), Instant.MIN).isAfter(restNow)).toList();
        if (idle.isEmpty()) {
            return null;
        }
        Instant now0 = clock.instant();
        int limit = atOnce;
        boolean full = limit > 0 && lanes.values().stream().filter(l -> l.online() && !l.idle()).count() >= limit;
        for (Long id : queue) {
            if (full && !chargingTask(id)) {
                continue; // as many robots work as the building carries: the others stay parked
            }
            Instant pause = notBefore.get(id);
            if (pause != null && now0.isBefore(pause)) {
                continue; // queued again after congestion: the others move on first
            }
            TaskCall call = calls.get(id);
            Optional<Claims.Holder> held = claims.holder(id, claimed(id, call));
            if (held.isPresent()) {
                if (!held.get().equals(waitedFor.put(id, held.get()))) {
                    String why = "waiting for " + held.get().describe();
                    Instant now = clock.instant();
                    store.insertEvent(id, "waiting", null, why, now);
                    store.updateTask(id, TaskState.QUEUED, null, preferred.get(id), why, now);
                    nowWaiting.add(id);
                }
                continue;
            }
            String wanted = preferred.get(id);
            // queued again after congestion on a robot that has left dispatch since: any robot takes it
            String want = wanted != null && (notBefore.containsKey(id) || chargingStopped.containsKey(id))
                    && (lanes.get(wanted) == null || !lanes.get(wanted).online()) ? null : wanted;
            List<RobotLane> candidates = want == null ? idle : idle.stream().filter(l -> l.name().equals(want)).toList();
            // a robot low on battery takes only its charging task
            candidates = candidates.stream().filter(l -> lowCharge(l) == null || chargingTask(id)).toList();
            if (!candidates.isEmpty()) {
                return new Choice(id, call, candidates);
            }
        }
        return null;
    }

    private Set<String> claimed(long id, TaskCall call) {
        return claimed.computeIfAbsent(id, k -> claims.claimedBy(call.task(), call.values()));
    }

    private void dispatch(Choice choice, long start) {
        TaskInstance task = new ModelTask(catalog.schema(), choice.call().task(), choice.call().values());
        GoalInstance first = task.goals().isEmpty() ? null : task.goals().get(0);
        RobotLane best = null;
        int bestCost = Integer.MAX_VALUE;
        StringBuilder why = new StringBuilder();
        Map<RobotLane, State> seen = new LinkedHashMap<>();
        for (RobotLane lane : choice.candidates()) {
            String estimate;
            int cost;
            try {
                State s = lane.stateSource().currentState();
                seen.put(lane, s);
                if (first == null || first.isSatisfiedIn(s)) {
                    cost = 0;
                    estimate = "0 actions";
                } else {
                    GoalSolver.Outcome o = estimator.plan(first.name(), first.args(), s);
                    cost = o.planned() ? o.plan().size() : Integer.MAX_VALUE - 1;
                    estimate = o.planned() ? o.plan().size() + " action(s)" : "no plan";
                }
            } catch (Exception e) {
                cost = Integer.MAX_VALUE;
                estimate = "state unreadable: " + e.getMessage();
            }
            if (why.length() > 0) {
                why.append(", ");
            }
            why.append(lane.name()).append(": ").append(estimate);
            if (best == null || cost < bestCost) {
                best = lane;
                bestCost = cost;
            }
        }
        Instant now = clock.instant();
        synchronized (lock) {
            if (!queue.contains(choice.task()) || !best.idle() || !best.online()) {
                return;
            }
            if (notBefore.containsKey(choice.task()) && bestCost >= Integer.MAX_VALUE - 1) {
                // queued again after congestion, and no idle robot can plan its next goal from where it stands (the robot
                // that ran it may carry its objects): it waits for one that can, and the others' tasks go first
                java.time.Duration wait = congestionPause.compareTo(java.time.Duration.ofSeconds(1)) < 0 ? java.time.Duration.ofSeconds(1) : congestionPause;
                notBefore.put(choice.task(), now.plus(wait));
                return;
            }
            if (claims.holder(choice.task(), claimed(choice.task(), choice.call())).isPresent()) {
                return; // taken meanwhile: the next round says what it waits for
            }
            Claims.Holder waited = waitedFor.get(choice.task());
            GoalInstance last = task.goals().isEmpty() ? null : task.goals().get(task.goals().size() - 1);
            if (waited != null && last != null && seen.get(best) != null && last.isSatisfiedIn(seen.get(best))) {
                refuse(choice.task(), "refused: while it waited for " + waited.describe() + ", that task ended and " + last.describe()
                        + " holds now for " + best.name() + "; the task was not executed, so nothing is done twice", now);
                return;
            }
            String text = "dispatched to " + best.name() + (first == null ? "" : "; first goal " + first.describe() + " from each robot's state: " + why);
            // the database first: if it fails the task stays queued, in memory and on disk
            store.dispatchTask(choice.task(), best.name(), text, now);
            waitedFor.remove(choice.task());
            queue.remove(choice.task());
            preferred.remove(choice.task());
            notBefore.remove(choice.task());
            chargingStopped.remove(choice.task());
            claims.release(choice.task()); // what it kept while queued again after congestion: taken afresh, on this robot
            claims.take(choice.task(), best.name(), claimed(choice.task(), choice.call()));
            dispatchedAt.put(choice.task(), now);
            best.start(choice.task(), task);
            long took = System.nanoTime() - start;
            dispatchNanos += took;
            dispatches++;
            if (dispatchTimes.size() < 100_000) {
                dispatchTimes.add(took);
            }
        }
        publishTask(choice.task(), false);
        publish(new LiveEvent("robot", view(best)));
    }

    // ---- Status from the robots' RefArcs -------------------------------------------------------

    private void onStatus(RobotLane lane, long taskId, Status status) {
        if (!running) {
            // the service is stopping: the task stays 'running' in the database and is recovered as interrupted
            return;
        }
        if (status instanceof Status.TaskQueued) {
            return;
        }
        boolean last = status instanceof Status.TaskCompleted || status instanceof Status.TaskAborted;
        String stop = lane.stopReason().orElse(null);
        boolean stopAborts = lane.stopAborts();
        Instant now = clock.instant();
        // the robot leaves dispatch before the task's end is written, so whoever reads the abort sees it out
        String takenOut = null;
        // the building's congestion ended the task: queued again (bounded), on the robot that ran it, after a pause
        String requeued = null;
        if (status instanceof Status.TaskAborted a && stop == null) {
            synchronized (lock) {
                takenOut = takeOutIfFailing(lane, taskId, a);
                if (a.cause() == Failure.Cause.CONGESTION && dispatching) {
                    requeued = congestionRequeue(lane, taskId, a, now);
                }
            }
        }
        String again = requeued;
        try {
            if (LEASE_LOST.equals(stop)) {
                // the instance that took the lease over owns the task now and has queued it again: write nothing
                return;
            }
            String[] event = { kind(status), status.toString() };
            if (status instanceof Status.TaskCompleted) {
                durably(() -> store.finishTask(taskId, lane.name(), List.<String[]>of(event), TaskState.COMPLETED, lane.name(), null, null, now));
            } else if (status instanceof Status.TaskAborted a) {
                if (stop != null && stop.startsWith("cancelled")) {
                    durably(() -> store.finishTask(taskId, lane.name(), List.<String[]>of(event), TaskState.CANCELLED, lane.name(), stop, null, now));
                } else if (stop != null && !stopAborts) {
                    String[] interrupted = { "interrupted", "interrupted: " + stop + "; queued again" };
                    durably(() -> store.finishTask(taskId, lane.name(), List.of(event, interrupted), TaskState.QUEUED, null, stop, null, now));
                } else if (again != null) {
                    String[] requeue = { "congestion_requeued", again };
                    // its robot is preferred in memory only: after a restart any robot may take it, from the state it sees
                    durably(() -> store.finishTask(taskId, lane.name(), List.of(event, requeue), TaskState.QUEUED, null, again, null, now));
                } else {
                    // a robot that is gone: its true cause, whatever step RefArc was at when it noticed
                    String cause = stopAborts && stop != null && !a.reason().contains(stop) ? stop + " (" + a.reason() + ")"
                            : a.cause() == Failure.Cause.CONGESTION && dispatching
                                    ? a.reason() + "; the building's congestion ended this task " + (CONGESTION_REQUEUES + 1)
                                            + " times (queued again " + CONGESTION_REQUEUES + " times): the jam does not clear by itself"
                                    : a.cause() == Failure.Cause.REFUSED ? REFUSED + a.reason() : a.reason();
                    String[] request = { "remote_operation", "remote operation requested: " + cause };
                    durably(() -> store.finishTask(taskId, lane.name(), List.of(event, request), TaskState.ABORTED, lane.name(), cause,
                            new String[] { a.goal().describe(), cause }, now));
                    if (takenOut != null) {
                        store.insertEvent(taskId, "robot_out", lane.name(), "robot " + lane.name() + " " + takenOut, now);
                    }
                }
            } else {
                durably(() -> store.insertEvent(taskId, event[0], lane.name(), event[1], now));
            }
        } catch (ServiceError e) {
            // the service stops, or this instance lost the lease: the task's row keeps its last state and is recovered
            System.err.println("triad serve: " + e.getMessage());
        } finally {
            if (last) {
                synchronized (lock) {
                    boolean toCharge = stop != null && stop.startsWith(CHARGING_STOP) && !stopAborts && dispatching;
                    if (stop != null && !stop.startsWith("cancelled") && !LEASE_LOST.equals(stop) && !stopAborts && dispatching) {
                        if (toCharge) {
                            preferred.put(taskId, lane.name());
                            chargingStopped.put(taskId, lane.name());
                        }
                        queue.add(taskId);
                    }
                    boolean ownCharging = taskId == sentToCharge.getOrDefault(lane.name(), -1L);
                    if (ownCharging && again != null) {
                        // its charging task, queued again after congestion, stays its own: taken by whichever idle robot could
                        // plan it, it charged another robot while this one stayed low with no charging task left (the
                        // mixed benchmark at 30x: 7 of 9 couriers stood below the threshold, their charging tasks run by others)
                        preferred.put(taskId, lane.name());
                    } else if (ownCharging && lowCharge(lane) != null) {
                        // its charging task ended and it is still low (it could not reach the dock): what it was stopped
                        // for goes to any robot, which plans it from the building's state (or is refused with the reason)
                        chargingStopped.entrySet().removeIf(e -> {
                            if (e.getValue().equals(lane.name())) {
                                preferred.remove(e.getKey());
                                return true;
                            }
                            return false;
                        });
                        if (status instanceof Status.TaskAborted a && a.cause() != Failure.Cause.REFUSED) {
                            // aborted on the way (not proven impossible, nor done without charging it): a new charging task
                            // is queued for it at the next round
                            sentToCharge.remove(lane.name());
                        }
                    }
                    Instant began = dispatchedAt.remove(taskId);
                    if (again != null || toCharge) {
                        // it keeps what it holds (the robot may carry it): no other task gets those objects meanwhile
                        queue.add(taskId);
                    } else {
                        // what the robot may still carry after an abort is gone from the world for the others
                        claims.release(taskId);
                    }
                    if (status instanceof Status.TaskCompleted) {
                        if (began != null) {
                            durations.addLast(java.time.Duration.between(began, now));
                            if (durations.size() > 50) {
                                durations.removeFirst();
                            }
                        }
                        claimed.remove(taskId);
                        jammedInARow.remove(lane.name());
                        resting.remove(lane.name());
                        lane.completed();
                    }
                    lane.finished(taskId);
                    lock.notifyAll();
                }
            }
        }
        try {
            if (status instanceof Status.TaskAborted) {
                publishRequests();
            }
            publishTask(taskId, false);
            publish(new LiveEvent("robot", view(lane)));
        } catch (ServiceError e) {
            // the pages catch up at the next event once the database answers again
        }
    }

    /**
     * Counts the abort and takes a robot on which {@link #ABORTS_IN_A_ROW} tasks in a row aborted out of dispatch; returns
     * why it was taken out, or null; call with the lock held.
     */
    private String takeOutIfFailing(RobotLane lane, long taskId, Status.TaskAborted abort) {
        if (abort.cause() == Failure.Cause.CONGESTION || abort.cause() == Failure.Cause.REFUSED) {
            return null; // the building's jam, or the models' proof that the task cannot be done from here: not the robot's fault
        }
        int inARow = lane.aborted();
        if (inARow >= ABORTS_IN_A_ROW && lane.online()) {
            String why = "taken out of dispatch: " + inARow + " tasks in a row aborted on it, the last (task " + taskId + ") with: " + abort.reason()
                    + "; put it back online when it is fixed";
            lane.takeOut(why);
            return why;
        }
        return null;
    }

    /**
     * A task that the building's congestion ended goes back to the queue, at most {@link #CONGESTION_REQUEUES} times (counted
     * on its timeline, so a restart does not reset it), not before a pause that grows with each time, on an idle robot that
     * can plan its next goal from where it stands (the one that ran it, when it carries the task's objects, which stay
     * claimed by the task meanwhile); the robot that ran it rests a pause per run that congestion ended in a row (at most
     * {@link #MAX_REST_PAUSES}), so that it does not meet the same jam with the next task at once. Set before the abort is written,
     * so that no look at the database queues it without them. Returns the timeline's text, or null when the bound is
     * reached (the task ends aborted). Call with the lock held.
     */
    private String congestionRequeue(RobotLane lane, long taskId, Status.TaskAborted abort, Instant now) {
        long before = store.events(taskId).stream().filter(e -> e.kind().equals("congestion_requeued")).count();
        if (before >= CONGESTION_REQUEUES) {
            return null;
        }
        java.time.Duration pause = congestionPause.multipliedBy(before + 1);
        notBefore.put(taskId, now.plus(pause));
        int jams = Math.min(MAX_REST_PAUSES, jammedInARow.merge(lane.name(), 1, Integer::sum));
        java.time.Duration rest = congestionPause.multipliedBy(jams);
        resting.put(lane.name(), now.plus(rest));
        return "the building's congestion ended the run, not the robot: queued again (" + (before + 1) + " of " + CONGESTION_REQUEUES
                + "), to run in " + pause.toSeconds() + " s on an idle robot that can plan it from where it stands; " + lane.name()
                + " rests " + rest.toSeconds() + " s: " + abort.reason();
    }

    /** The pause before a task queued again after congestion runs again (times the how-manieth time); tests shorten it. */
    public void congestionPause(java.time.Duration pause) {
        if (pause.isNegative()) {
            throw new IllegalArgumentException("a pause is not negative: " + pause);
        }
        congestionPause = pause;
    }

    /** Ends a queued task without executing it, for {@code reason}; call with the lock held. */
    private void refuse(long taskId, String reason, Instant now) {
        store.insertEvent(taskId, "refused", null, reason, now);
        store.updateTask(taskId, TaskState.REFUSED, null, null, reason, now);
        queue.remove(taskId);
        preferred.remove(taskId);
        claimed.remove(taskId);
        waitedFor.remove(taskId);
        notBefore.remove(taskId);
        claims.release(taskId);
        refusedToPublish.add(taskId);
    }

    private void abort(long taskId, String robot, String goal, String reason, Instant now) {
        store.updateTask(taskId, TaskState.ABORTED, robot, null, reason, now);
        store.insertRequest(taskId, robot, goal, reason, now);
        store.insertEvent(taskId, "remote_operation", robot, "remote operation requested: " + reason, now);
    }

    private static String kind(Status s) {
        String n = s.getClass().getSimpleName();
        return n.replaceAll("([a-z])([A-Z])", "$1_$2").toLowerCase(java.util.Locale.ROOT);
    }

    // ---- views --------------------------------------------------------------------------------

    private TaskRow require(long id) {
        return store.task(id).orElseThrow(() -> new ServiceError(404, "not-found", "no task " + id));
    }

    /**
     * Expected start and finish of the running and queued tasks: each takes the median wall-clock time
     * of the last 50 completed tasks (dispatch to completion); queued tasks go, in dispatch order, to
     * whichever online robot is expected free first. Waiting for claims and preferred robots are not
     * modelled; empty until a task has completed or while no robot is online.
     */
    private Map<Long, Instant[]> forecast() {
        synchronized (lock) {
            if (durations.isEmpty()) {
                return Map.of();
            }
            List<java.time.Duration> sorted = new ArrayList<>(durations);
            sorted.sort(null);
            java.time.Duration d = sorted.get(sorted.size() / 2);
            Instant now = clock.instant();
            Map<Long, Instant[]> out = new java.util.HashMap<>();
            java.util.PriorityQueue<Instant> free = new java.util.PriorityQueue<>();
            for (RobotLane l : lanes.values()) {
                Optional<Long> current = l.currentTask();
                if (current.isPresent()) {
                    Instant began = dispatchedAt.getOrDefault(current.get(), now);
                    Instant end = began.plus(d).isBefore(now) ? now : began.plus(d);
                    out.put(current.get(), new Instant[] { began, end });
                    if (l.online()) {
                        free.add(end);
                    }
                } else if (l.online()) {
                    free.add(now);
                }
            }
            if (!free.isEmpty()) {
                for (Long id : queue) {
                    Instant start = free.poll();
                    out.put(id, new Instant[] { start, start.plus(d) });
                    free.add(start.plus(d));
                }
            }
            return out;
        }
    }

    private TaskView view(TaskRow t, boolean withEvents) {
        return view(t, withEvents ? store.events(t.id()).stream().map(FleetService::view).toList() : null,
                t.state() == TaskState.QUEUED || t.state() == TaskState.RUNNING ? forecast() : Map.of());
    }

    private TaskView view(TaskRow t, List<EventView> events, Map<Long, Instant[]> forecast) {
        JsonNode args;
        try {
            args = JSON.readTree(t.args());
        } catch (JsonProcessingException e) {
            args = JSON.createObjectNode();
        }
        String call = Optional.ofNullable(calls.get(t.id())).map(TaskCall::describe).orElseGet(() -> callText(t));
        Instant[] expected = t.state() == TaskState.QUEUED || t.state() == TaskState.RUNNING ? forecast.get(t.id()) : null;
        return new TaskView(t.id(), t.task(), args, call, t.state().json(), t.robot(), t.preferredRobot(), t.reason(), Views.time(t.submittedAt()),
                Views.time(t.updatedAt()), events, t.priority(), expected == null ? null : Views.time(expected[0]),
                expected == null ? null : Views.time(expected[1]));
    }

    private static String callText(TaskRow t) {
        try {
            List<String> values = new ArrayList<>();
            JSON.readTree(t.args()).elements().forEachRemaining(v -> values.add(v.isTextual() ? v.textValue() : v.toString()));
            return t.task() + "(" + String.join(", ", values) + ")";
        } catch (JsonProcessingException e) {
            return t.task() + "(?)";
        }
    }

    private static EventView view(EventRow e) {
        return new EventView(e.id(), Views.time(e.at()), e.kind(), e.robot(), e.text());
    }

    private RobotView view(RobotLane l) {
        FleetRobot r = l.robot();
        return new RobotView(l.name(), l.online(), l.currentTask().orElse(null), l.currentCall(), l.plan(), l.step(), r.floor().isPresent(),
                l.online() ? null : l.offlineReason(), l.isGone() ? "gone" : l.online() ? "online" : "offline", quietly(r::pose), quietly(r::battery),
                batteryNote(l));
    }

    /** What a platform reports, or null when it reports nothing or fails to (a view never fails for it). */
    private static <T> T quietly(java.util.function.Supplier<Optional<T>> read) {
        try {
            return read.get().orElse(null);
        } catch (RuntimeException e) {
            return null;
        }
    }

    private TaskView publishTask(long id, boolean withEvents) {
        TaskView v = store.task(id).map(t -> view(t, withEvents)).orElseThrow();
        if (!listeners.isEmpty()) {
            List<EventRow> events = store.events(id);
            EventRow last = events.isEmpty() ? null : events.get(events.size() - 1);
            Map<String, Object> data = new LinkedHashMap<>();
            data.put("task", withEvents ? withoutEvents(v) : v);
            data.put("event", last == null ? null : view(last));
            publish(new LiveEvent("task", data));
        }
        return v;
    }

    private static TaskView withoutEvents(TaskView v) {
        return new TaskView(v.id(), v.task(), v.args(), v.call(), v.state(), v.robot(), v.preferredRobot(), v.reason(), v.submittedAt(), v.updatedAt(), null,
                v.priority(), v.expectedStart(), v.expectedFinish());
    }

    private void publishRequests() {
        if (!listeners.isEmpty()) {
            publish(new LiveEvent("requests", requests(false)));
        }
    }

    private void publish(LiveEvent e) {
        for (Consumer<LiveEvent> l : listeners) {
            try {
                l.accept(e);
            } catch (RuntimeException ex) {
                listeners.remove(l);
            }
        }
    }

    private static void sleepQuietly(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The database's health and who dispatches, for the operator page. */
    public Views.HealthView health() {
        StoreHealth h = store.health();
        return new Views.HealthView(store.database().shown(), h.ok(), h.outages().stream().map(StoreHealth.Outage::describe).toList(),
                store.database().shared(), dispatching, List.copyOf(leaseHistory));
    }

    @Override
    public void close() {
        running = false;
        dispatcher.interrupt();
        for (RobotLane l : lanes.values()) {
            l.close();
        }
        lease.close();
    }
}
