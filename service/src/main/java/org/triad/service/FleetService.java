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

    private final TaskCatalog catalog;
    private final TaskStore store;
    private final GoalSolver estimator;
    private final Clock clock;
    private final Map<String, RobotLane> lanes = new LinkedHashMap<>();
    private final List<Consumer<LiveEvent>> listeners = new CopyOnWriteArrayList<>();
    private final Object lock = new Object();
    /** Queued task ids in queue order (= submission order; a retried task keeps its place in front). */
    private final Map<Long, Integer> priorities = new ConcurrentHashMap<>();
    /** Queued task ids in dispatch order: higher priority first, then submission order (a retried task keeps its place). */
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

    public FleetService(TaskCatalog catalog, TaskStore store, List<FleetRobot> robots, GoalSolver planner, Clock clock) {
        this.catalog = catalog;
        this.store = store;
        this.estimator = planner;
        this.clock = clock;
        this.claims = new Claims(catalog.schema());
        GoalPlanner goalPlanner = new org.triad.refarc.model.SchemaGoalPlanner(planner);
        for (FleetRobot r : robots) {
            lanes.put(r.name(), new RobotLane(r, goalPlanner, this::onStatus));
        }
        recover();
        dispatcher = new Thread(this::dispatchLoop, "triad-dispatcher");
        dispatcher.setDaemon(true);
        dispatcher.start();
    }

    /** Tasks that were running when the service stopped are interrupted and queued again; queued ones stay queued. */
    private void recover() {
        Instant now = clock.instant();
        for (TaskRow t : store.tasksInOrder(TaskState.RUNNING)) {
            store.insertEvent(t.id(), "interrupted", t.robot(), "interrupted: the service stopped while robot " + t.robot()
                    + " ran the task; queued again, to be re-planned from the robot's current state", now);
            store.updateTask(t.id(), TaskState.QUEUED, null, null, "interrupted by a service restart", now);
        }
        for (TaskRow t : store.tasksInOrder(TaskState.QUEUED)) {
            try {
                TaskCall call = catalog.check(request(t));
                calls.put(t.id(), call);
                priorities.put(t.id(), t.priority());
                queue.add(t.id());
                if (t.preferredRobot() != null) {
                    preferred.put(t.id(), t.preferredRobot());
                }
            } catch (ServiceError e) {
                abort(t.id(), null, null, "the task no longer fits the models or the world: " + e.getMessage(), now);
            }
        }
    }

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
        TaskCall call = catalog.check(body);
        Instant now = clock.instant();
        TaskRow row;
        synchronized (lock) {
            row = store.insertTask(call.task(), call.args().toString(), call.priority(), now);
            store.insertEvent(row.id(), "submitted", null, "submitted: " + call.describe() + (call.priority() == 0 ? "" : " with priority "
                    + call.priority()), now);
            calls.put(row.id(), call);
            priorities.put(row.id(), call.priority());
            queue.add(row.id());
            lock.notifyAll();
        }
        return publishTask(row.id(), true);
    }

    public Optional<TaskView> task(long id) {
        return store.task(id).map(t -> view(t, true));
    }

    public List<TaskView> tasks(TaskState state, int limit) {
        Map<Long, Instant[]> forecast = forecast();
        return store.tasks(state, limit).stream().map(t -> view(t, false, forecast)).toList();
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
                    store.resolveRequests(id, "cancelled", now);
                    store.insertEvent(id, "cancelled", t.robot(), "cancelled by " + who, now);
                    store.updateTask(id, TaskState.CANCELLED, t.robot(), null, "cancelled by " + who, now);
                }
                case RUNNING -> {
                    RobotLane lane = lanes.get(t.robot());
                    store.insertEvent(id, "cancelling", t.robot(), "cancel requested by " + who + "; the robot stops at its next step", now);
                    if (lane != null) {
                        lane.stop("cancelled by " + who);
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
        return lanes.values().stream().map(this::view).toList();
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

    /** Mean time the dispatcher took to choose a robot (estimates included), ns, and how many dispatches. */
    public long[] dispatchStatistics() {
        return new long[] { dispatches == 0 ? 0 : dispatchNanos / dispatches, dispatches };
    }

    // ---- dispatch -----------------------------------------------------------------------------

    private record Choice(long task, TaskCall call, List<RobotLane> candidates) {
    }

    private void dispatchLoop() {
        while (running) {
            Choice choice;
            List<Long> nowWaiting = new ArrayList<>();
            synchronized (lock) {
                try {
                    choice = next(nowWaiting);
                } catch (RuntimeException e) {
                    // the database failed while recording a wait: the dispatcher lives on and tries again
                    System.err.println("triad serve: dispatch: " + e.getMessage());
                    choice = null;
                }
                if (choice == null && nowWaiting.isEmpty()) {
                    try {
                        lock.wait(500);
                    } catch (InterruptedException e) {
                        return;
                    }
                    continue;
                }
            }
            nowWaiting.forEach(id -> publishTask(id, false));
            if (choice == null) {
                continue;
            }
            long start = System.nanoTime();
            try {
                dispatch(choice, start);
                for (Long refused : refusedToPublish) {
                    refusedToPublish.remove(refused);
                    publishTask(refused, false);
                }
            } catch (ServiceError e) {
                // the database failed: the task stays queued in the database and is tried again
                sleepQuietly(500);
            } catch (RuntimeException e) {
                synchronized (lock) {
                    queue.remove(choice.task());
                    abort(choice.task(), null, null, "the service could not dispatch the task: " + e, clock.instant());
                }
                publishRequests();
            }
        }
    }

    /**
     * The oldest queued task some idle online robot may take, with those robots. A task one of whose
     * objects another running task holds waits (it keeps its place; later tasks may go first); its
     * reason says for what, and is recorded once per holder in {@code nowWaiting}.
     */
    private Choice next(List<Long> nowWaiting) {
        List<RobotLane> idle = lanes.values().stream().filter(l -> l.online() && l.idle()).toList();
        if (idle.isEmpty()) {
            return null;
        }
        for (Long id : queue) {
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
            String want = preferred.get(id);
            List<RobotLane> candidates = want == null ? idle : idle.stream().filter(l -> l.name().equals(want)).toList();
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
            if (claims.holder(choice.task(), claimed(choice.task(), choice.call())).isPresent()) {
                return; // taken meanwhile: the next round says what it waits for
            }
            Claims.Holder waited = waitedFor.remove(choice.task());
            GoalInstance last = task.goals().isEmpty() ? null : task.goals().get(task.goals().size() - 1);
            if (waited != null && last != null && seen.get(best) != null && last.isSatisfiedIn(seen.get(best))) {
                refuse(choice.task(), "refused: while it waited for " + waited.describe() + ", that task ended and " + last.describe()
                        + " holds now for " + best.name() + "; the task was not executed, so nothing is done twice", now);
                return;
            }
            queue.remove(choice.task());
            preferred.remove(choice.task());
            claims.take(choice.task(), best.name(), claimed(choice.task(), choice.call()));
            dispatchedAt.put(choice.task(), now);
            String text = "dispatched to " + best.name() + (first == null ? "" : "; first goal " + first.describe() + " from each robot's state: " + why);
            store.insertEvent(choice.task(), "dispatched", best.name(), text, now);
            store.updateTask(choice.task(), TaskState.RUNNING, best.name(), null, null, now);
            best.start(choice.task(), task);
            dispatchNanos += System.nanoTime() - start;
            dispatches++;
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
        Instant now = clock.instant();
        try {
            if (status instanceof Status.TaskQueued) {
                return;
            }
            store.insertEvent(taskId, kind(status), lane.name(), status.toString(), now);
            if (status instanceof Status.TaskCompleted) {
                synchronized (lock) {
                    store.updateTask(taskId, TaskState.COMPLETED, lane.name(), null, null, now);
                    Instant began = dispatchedAt.remove(taskId);
                    if (began != null) {
                        durations.addLast(java.time.Duration.between(began, now));
                        if (durations.size() > 50) {
                            durations.removeFirst();
                        }
                    }
                    claims.release(taskId);
                    claimed.remove(taskId);
                    lane.completed();
                    lane.finished(taskId);
                    lock.notifyAll();
                }
            } else if (status instanceof Status.TaskAborted a) {
                String stop = lane.stopReason().orElse(null);
                synchronized (lock) {
                    if (stop != null && stop.startsWith("cancelled")) {
                        store.updateTask(taskId, TaskState.CANCELLED, lane.name(), null, stop, now);
                    } else if (stop != null) {
                        store.insertEvent(taskId, "interrupted", lane.name(), "interrupted: " + stop + "; queued again", now);
                        store.updateTask(taskId, TaskState.QUEUED, null, null, stop, now);
                        queue.add(taskId);
                    } else {
                        abort(taskId, lane.name(), a.goal().describe(), a.reason(), now);
                        int inARow = lane.aborted();
                        if (inARow >= ABORTS_IN_A_ROW && lane.online()) {
                            String why = "taken out of dispatch: " + inARow + " tasks in a row aborted on it, the last (task " + taskId + ") with: "
                                    + a.reason() + "; put it back online when it is fixed";
                            lane.takeOut(why);
                            store.insertEvent(taskId, "robot_out", lane.name(), "robot " + lane.name() + " " + why, now);
                        }
                    }
                    claims.release(taskId); // what the robot may still carry is gone from the world for the others
                    dispatchedAt.remove(taskId);
                    lane.finished(taskId);
                    lock.notifyAll();
                }
                publishRequests();
            }
        } catch (ServiceError e) {
            // the database failed; the task's row keeps its last state and is recovered at the next start
            System.err.println("triad serve: " + e.getMessage());
        }
        publishTask(taskId, false);
        publish(new LiveEvent("robot", view(lane)));
    }

    /** Ends a queued task without executing it, for {@code reason}; call with the lock held. */
    private void refuse(long taskId, String reason, Instant now) {
        queue.remove(taskId);
        preferred.remove(taskId);
        claimed.remove(taskId);
        store.insertEvent(taskId, "refused", null, reason, now);
        store.updateTask(taskId, TaskState.REFUSED, null, null, reason, now);
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
                Optional<Long> running = l.currentTask();
                if (running.isPresent()) {
                    Instant began = dispatchedAt.getOrDefault(running.get(), now);
                    Instant end = began.plus(d).isBefore(now) ? now : began.plus(d);
                    out.put(running.get(), new Instant[] { began, end });
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
        return view(t, withEvents, t.state() == TaskState.QUEUED || t.state() == TaskState.RUNNING ? forecast() : Map.of());
    }

    private TaskView view(TaskRow t, boolean withEvents, Map<Long, Instant[]> forecast) {
        List<EventView> events = withEvents ? store.events(t.id()).stream().map(FleetService::view).toList() : null;
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
        return new RobotView(l.name(), l.online(), l.currentTask().orElse(null), l.currentCall(), l.plan(), l.step(), l.robot().floor().isPresent(),
                l.online() ? null : l.offlineReason());
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

    @Override
    public void close() {
        running = false;
        dispatcher.interrupt();
        for (RobotLane l : lanes.values()) {
            l.close();
        }
    }
}
