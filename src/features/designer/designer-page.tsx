"use client";
// The experiment designer: library (left), protocol timeline (centre),
// properties and checks (right). Every edit is a command of the headless
// model; this page only renders the draft and turns gestures into commands.
import {
  DndContext,
  DragOverlay,
  PointerSensor,
  useSensor,
  useSensors,
  type DragEndEvent,
  type DragStartEvent,
} from "@dnd-kit/core";
import { useQuery } from "@tanstack/react-query";
import { ArrowLeft, Plus, Redo2, Undo2 } from "lucide-react";
import Link from "next/link";
import { useCallback, useDeferredValue, useEffect, useMemo, useRef, useState } from "react";
import { studyRoleMay } from "@/core/access/policy";
import { actionName, actionNamesOf } from "@/core/designer/action-name";
import { blockFor as findBlock, initialParameters, RUN_TOGETHER, type Block } from "@/core/designer/blocks";
import { libraryEntries } from "@/core/designer/library";
import { commands } from "@/core/designer/model";
import { locateAction, locateStep } from "@/core/designer/draft";
import type { DesignDraft } from "@/core/designer/types";
import { hasErrors, validateDesign } from "@/core/designer/validate";
import { variantIssues } from "@/core/designer/variant-issues";
import { abstractAction, audioPlayer, eventName, eventNamesOf, type Plugin } from "@/core/plugins";
import { newId } from "@/lib/new-id";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { isTyping, useKeys } from "@/ui/use-keys";
import { Input, NativeSelect } from "@/ui/field";
import { Problem } from "@/ui/problem";
import { Spinner } from "@/ui/surface";
import { Tabs } from "@/ui/tabs";
import { FlowMap } from "./flow-map";
import { IssuesPanel } from "./issues-panel";
import { LibraryPanel } from "./library-panel";
import { documentsOf, PluginChoice } from "./plugin-choice";
import { PropertiesPanel } from "./properties-panel";
import { ProtocolTimeline, type Marks, type Selection } from "./protocol-timeline";
import { RehearsalPreview } from "./rehearsal-preview";
import { collision, TIMELINE_END, TimelineEnd } from "./timeline-end";
import { useConditionNames } from "./use-conditions";
import { useDesigner, type SaveState } from "./use-designer";
import { VersionsPanel } from "./versions-panel";

// A click is not a drag: the pointer must travel a little first. A constant,
// because new options would make dnd-kit re-render every block on each edit.
const POINTER = { activationConstraint: { distance: 5 } };

export function DesignerPage({ experimentId }: { experimentId: string }) {
  const trpc = useTRPC();
  const designer = useDesigner(experimentId);
  const { draft } = designer;
  const study = useQuery({
    ...trpc.studies.get.queryOptions({ studyId: designer.loaded.data?.studyId ?? "" }),
    enabled: Boolean(designer.loaded.data),
  });
  const robots = useQuery(trpc.plugins.list.queryOptions());
  // The stored choice is of the stored robot's documents: a robot changed since (saving clears it) runs the default.
  const stored = designer.loaded.data;
  const pluginSource = stored && stored.robotId === draft?.robotId ? stored.pluginSource : null;
  const robotSaved = designer.save.kind === "saved" && stored?.robotId !== draft?.robotId;
  const { refetch } = designer.loaded;
  // Once a new robot is saved, read the stored experiment again: its documents can then be chosen.
  useEffect(() => {
    if (robotSaved) void refetch();
  }, [robotSaved, refetch]);
  const pluginQuery = useQuery({
    ...trpc.plugins.get.queryOptions({ robotId: draft?.robotId ?? "", source: pluginSource }),
    enabled: Boolean(draft?.robotId),
  });
  const plugin = (pluginQuery.data ?? null) as Plugin | null;
  const [selection, setSelection] = useState<Selection>(null);
  const [view, setView] = useState("steps");

  const entries = useMemo(() => libraryEntries(plugin), [plugin]);
  const blockFor = useCallback((type: string) => findBlock(type, plugin), [plugin]);
  const blockName = useCallback((type: string) => findBlock(type, plugin)?.name ?? type, [plugin]);
  const names = useMemo(() => actionNamesOf(plugin), [plugin]);
  const eventNames = useMemo(() => eventNamesOf(plugin), [plugin]);

  // Checks run a beat behind typing: the timeline stays responsive on big protocols.
  const checked = useDeferredValue(draft);
  // Checked against this server's ways to the robot too: what it calls runnable, the runtime runs.
  const channels = robots.data?.channels;
  const conditions = useConditionNames(designer.loaded.data?.studyId, experimentId);
  const issues = useMemo(
    () => (checked ? [...validateDesign(checked, plugin, channels), ...variantIssues(checked, conditions)] : []),
    [checked, plugin, channels, conditions],
  );
  const marks = useMemo(() => {
    const map = new Map<string, Marks>();
    for (const issue of issues) {
      const key = issue.actionId ?? issue.stepId;
      if (!key) continue;
      const m = map.get(key) ?? { errors: [], warnings: [] };
      (issue.severity === "error" ? m.errors : m.warnings).push(issue.message);
      map.set(key, m);
    }
    return map;
  }, [issues]);
  const unsupported = useMemo(
    () => new Set(entries.filter((e) => plugin && isUnsupported(plugin, e.block.type)).map((e) => e.block.type)),
    [entries, plugin],
  );

  const role = study.data?.myRole;
  const canEdit = role ? studyRoleMay(role, "experiment.edit") : false;
  const canPublish = role ? studyRoleMay(role, "version.publish") : false;
  // Wizards and observers read the design; the server refuses their edits anyway.
  const run = useMemo(() => (canEdit ? designer.run : () => {}), [canEdit, designer.run]);

  // Read by stable callbacks, so the library does not re-render on every edit.
  const latest = useRef({ draft, selection });
  latest.current = { draft, selection };

  /** Where a block added without dragging goes: after the selected action, or at the end of the selected (or last) step. */
  const insertionPoint = useCallback(() => {
    const { draft, selection } = latest.current;
    if (!draft) return null;
    try {
      if (selection?.kind === "action") {
        const found = locateAction(draft, selection.id);
        return { stepId: found.step.id, index: found.index + 1 };
      }
      if (selection?.kind === "step")
        return { stepId: selection.id, index: locateStep(draft, selection.id).step.actions.length };
    } catch {
      // the selection was deleted: fall through to the last step
    }
    const last = draft.steps.at(-1);
    return last ? { stepId: last.id, index: last.actions.length } : null;
  }, []);

  const addBlock = useCallback(
    (block: Block, stepId: string, index: number) => {
      const id = newId();
      run(
        commands.addAction(
          stepId,
          index,
          { type: block.type, name: "", parameters: initialParameters(block, newId) },
          id,
        ),
      );
      setSelection({ kind: "action", id });
    },
    [run],
  );

  const { setNotice } = designer;
  const addFromLibrary = useCallback(
    (block: Block) => {
      if (block.type === RUN_TOGETHER.type) {
        const { selection } = latest.current;
        if (selection?.kind === "action") run(commands.setRunTogether(selection.id, true));
        else
          setNotice("Select the action that should start together with the one above it, then choose “Run together”.");
        return;
      }
      const at = insertionPoint();
      if (at) addBlock(block, at.stepId, at.index);
      else setNotice("Add a step first: blocks go into steps.");
    },
    [insertionPoint, addBlock, setNotice, run],
  );

  const addStep = () => {
    const id = newId();
    run(commands.addStep(`Step ${(draft?.steps.length ?? 0) + 1}`, undefined, id));
    setSelection({ kind: "step", id });
  };
  const firstStep = () => {
    const stepId = newId();
    run(commands.addStep("Step 1", undefined, stepId));
    return { stepId, index: 0 };
  };

  const moveSelected = useCallback(
    (delta: -1 | 1) => {
      if (!draft || !selection) return;
      if (selection.kind === "step")
        return run(commands.moveStep(selection.id, locateStep(draft, selection.id).index + delta));
      const { step, stepIndex, index } = locateAction(draft, selection.id);
      const to = index + delta;
      if (to >= 0 && to < step.actions.length) return run(commands.moveAction(selection.id, step.id, to));
      // Past the edge of its step, an action moves on into the neighbouring step.
      const neighbour = draft.steps[stepIndex + delta];
      if (neighbour) run(commands.moveAction(selection.id, neighbour.id, delta < 0 ? neighbour.actions.length : 0));
    },
    [draft, selection, run],
  );

  const deleteSelected = useCallback(() => {
    if (!selection) return;
    run(selection.kind === "step" ? commands.removeStep(selection.id) : commands.removeAction(selection.id));
    setSelection(null);
  }, [selection, run]);

  useDesignerKeys({
    undo: designer.undo,
    redo: designer.redo,
    move: moveSelected,
    remove: deleteSelected,
    enabled: canEdit,
  });

  const sensors = useSensors(useSensor(PointerSensor, POINTER));
  const [dragging, setDragging] = useState<string | null>(null);
  const onDragStart = (e: DragStartEvent) => setDragging(dragLabel(String(e.active.id), draft, blockName));
  const onDragEnd = (e: DragEndEvent) => {
    setDragging(null);
    if (!draft || !e.over) return;
    const [kind, id] = splitId(String(e.active.id));
    // Below an empty timeline, a block starts the first step.
    const drop =
      dropTarget(draft, String(e.over.id)) ??
      (e.over.id === TIMELINE_END && kind === "lib" && id !== RUN_TOGETHER.type ? firstStep() : null);
    if (!drop) return;
    if (kind === "lib" && id === RUN_TOGETHER.type) {
      // Onto an action: that one; onto a step's drop zone: its last action.
      const { step } = locateStep(draft, drop.stepId);
      const target = step.actions[Math.min(drop.index, step.actions.length - 1)];
      if (target) run(commands.setRunTogether(target.id, true));
    } else if (kind === "lib") {
      const block = findBlock(id, plugin);
      if (block) addBlock(block, drop.stepId, drop.index);
    } else if (kind === "act") {
      run(commands.moveAction(id, drop.stepId, drop.index));
    } else if (kind === "step") {
      run(commands.moveStep(id, locateStep(draft, drop.stepId).index));
    }
  };

  if (designer.loaded.isPending || (!draft && !designer.loaded.error)) return <Spinner label="Opening the designer…" />;
  if (designer.loaded.error || !draft) return <Problem error={designer.loaded.error} />;
  const robotName = robots.data?.robots.find((r) => r.robotId === draft.robotId)?.name ?? draft.robotId;
  // One entry per robot: several sources may offer the same robotId (the plugin choice tells them apart).
  const robotChoices = robots.data?.robots.filter((r) => r.isDefault) ?? [];
  // The document the draft runs now: a version is worth publishing when only this changed.
  const runs = documentsOf(robots.data?.robots ?? [], draft.robotId, pluginSource).used;
  const errors = hasErrors(issues);

  return (
    <div className="relative left-1/2 -my-8 flex h-[calc(100vh-3.5rem-1px)] w-screen -translate-x-1/2 flex-col gap-3 p-4">
      <header className="flex flex-wrap items-center gap-3">
        <Link
          href={`/studies/${designer.loaded.data!.studyId}`}
          className="text-slate-500 hover:text-slate-800"
          aria-label="Back to the study"
        >
          <ArrowLeft className="h-5 w-5" aria-hidden />
        </Link>
        <Input
          aria-label="Experiment name"
          className="h-9 max-w-xs font-semibold"
          value={draft.name}
          disabled={!canEdit}
          onChange={(e) => run(commands.setDetails({ name: e.target.value }))}
        />
        {/* biome-ignore lint/a11y/noLabelWithoutControl: the select inside is the control (a custom component the rule cannot see through) */}
        <label className="flex items-center gap-2 text-sm text-slate-600">
          Robot
          <NativeSelect
            aria-label="Robot"
            className="h-9 w-auto py-0"
            value={draft.robotId}
            disabled={!canEdit}
            onChange={(e) => run(commands.setRobot(e.target.value))}
          >
            {robotChoices.map((r) => (
              <option key={r.robotId} value={r.robotId}>
                {r.name}
              </option>
            ))}
          </NativeSelect>
        </label>
        {robots.data && (
          <PluginChoice
            experimentId={experimentId}
            robotId={draft.robotId}
            chosenSource={pluginSource}
            documents={robots.data.robots}
            canChoose={canEdit && stored?.robotId === draft.robotId}
          />
        )}
        <div className="ml-auto flex items-center gap-2">
          <SaveStatus save={designer.save} />
          <Button
            variant="ghost"
            size="sm"
            aria-label="Undo"
            title={`Undo ${designer.history?.past.at(-1)?.label ?? ""} (Ctrl+Z)`}
            disabled={!designer.history?.past.length || !canEdit}
            onClick={designer.undo}
          >
            <Undo2 className="h-4 w-4" aria-hidden />
          </Button>
          <Button
            variant="ghost"
            size="sm"
            aria-label="Redo"
            title={`Redo ${designer.history?.future[0]?.label ?? ""} (Ctrl+Shift+Z)`}
            disabled={!designer.history?.future.length || !canEdit}
            onClick={designer.redo}
          >
            <Redo2 className="h-4 w-4" aria-hidden />
          </Button>
        </div>
      </header>
      {designer.save.kind === "conflict" && (
        <div
          role="alert"
          className="flex flex-wrap items-center gap-3 rounded-md border border-amber-300 bg-amber-50 p-3 text-sm text-amber-900"
        >
          Someone else saved this experiment while you were editing it. Your latest changes are not saved yet.
          <Button size="sm" variant="secondary" onClick={() => void designer.loadTheirs()}>
            Load their version (drop my changes)
          </Button>
          <Button size="sm" onClick={() => void designer.keepMine()}>
            Keep my version (replace theirs)
          </Button>
        </div>
      )}
      {designer.save.kind === "failed" && <Problem error={{ message: `Not saved: ${designer.save.message}` }} />}
      {designer.notice && <Problem error={{ message: designer.notice }} />}
      <DndContext
        sensors={sensors}
        collisionDetection={collision}
        onDragStart={onDragStart}
        onDragEnd={onDragEnd}
        onDragCancel={() => setDragging(null)}
      >
        <div className="grid min-h-0 flex-1 grid-cols-[16rem_minmax(0,1fr)_24rem] gap-4">
          {canEdit ? (
            <LibraryPanel entries={entries} robotName={robotName} unsupported={unsupported} onAdd={addFromLibrary} />
          ) : (
            <p className="text-sm text-slate-500">
              You can read this experiment; only its owner and researchers edit it.
            </p>
          )}
          <main className="min-h-0 overflow-y-auto pr-1">
            <Tabs
              label="Designer views"
              value={view}
              onValueChange={setView}
              tabs={[
                {
                  id: "steps",
                  label: "Steps",
                  content: (
                    <div className="space-y-3">
                      <ProtocolTimeline
                        steps={draft.steps}
                        selection={selection}
                        marks={marks}
                        blockName={blockName}
                        onSelect={setSelection}
                      />
                      <TimelineEnd lastStep={draft.steps.at(-1)?.name ?? null}>
                        {canEdit && (
                          <Button variant="secondary" className="self-start" onClick={addStep}>
                            <Plus className="h-4 w-4" aria-hidden /> Add step
                          </Button>
                        )}
                      </TimelineEnd>
                    </div>
                  ),
                },
                {
                  id: "flow",
                  label: "Flow map",
                  content: <FlowMap draft={draft} onSelect={(id) => setSelection({ kind: "step", id })} />,
                },
                {
                  id: "rehearse",
                  label: "Rehearse",
                  content: (
                    <RehearsalPreview
                      draft={draft}
                      actionName={(a) => actionName(a, names)}
                      conditions={conditions}
                      eventName={(id) => eventName(id, eventNames)}
                      blocked={
                        errors
                          ? "Fix the problems listed on the right first: the preview walks the experiment as a trial would."
                          : null
                      }
                    />
                  ),
                },
              ]}
            />
          </main>
          <div className="min-h-0 space-y-3 overflow-y-auto">
            <fieldset disabled={!canEdit} className="min-w-0">
              <PropertiesPanel
                draft={draft}
                selection={selection}
                issues={issues}
                blockFor={blockFor}
                run={run}
                onMove={moveSelected}
                onDelete={deleteSelected}
                studyId={designer.loaded.data!.studyId}
                robotName={robotName}
                audioPlayer={audioPlayer(plugin)}
                robotEvents={plugin?.events ?? []}
                conditions={conditions}
              />
            </fieldset>
            <IssuesPanel
              draft={draft}
              issues={issues}
              robotName={robotName}
              audioPlayer={audioPlayer(plugin)}
              onSelect={setSelection}
            />
            <VersionsPanel
              experimentId={experimentId}
              draft={draft}
              pluginHash={runs?.hash}
              canPublish={canPublish}
              blocked={
                errors
                  ? "Fix the problems listed above to publish."
                  : designer.save.kind === "conflict"
                    ? "Resolve the editing conflict first."
                    : null
              }
              beforePublish={designer.saveNow}
            />
          </div>
        </div>
        <DragOverlay dropAnimation={null}>
          {dragging && (
            <div className="rounded-md border border-brand-500 bg-white px-3 py-1.5 text-sm shadow-lg">{dragging}</div>
          )}
        </DragOverlay>
      </DndContext>
    </div>
  );
}

function splitId(id: string): [string, string] {
  const colon = id.indexOf(":");
  return [id.slice(0, colon), id.slice(colon + 1)];
}

/** A drop on an action inserts before it; on a step's header or drop zone, at its end. */
function dropTarget(draft: DesignDraft, overId: string): { stepId: string; index: number } | null {
  const [kind, id] = splitId(overId);
  try {
    if (kind === "act") {
      const found = locateAction(draft, id);
      return { stepId: found.step.id, index: found.index };
    }
    if (kind === "step" || kind === "drop") return { stepId: id, index: locateStep(draft, id).step.actions.length };
    if (kind === "end") {
      const last = draft.steps.at(-1);
      return last ? { stepId: last.id, index: last.actions.length } : null;
    }
  } catch {
    return null;
  }
  return null;
}

function dragLabel(activeId: string, draft: DesignDraft | null, blockName: (t: string) => string) {
  const [kind, id] = splitId(activeId);
  if (kind === "lib") return id === RUN_TOGETHER.type ? RUN_TOGETHER.name : blockName(id);
  if (!draft) return null;
  try {
    if (kind === "step") return locateStep(draft, id).step.name;
    const { action } = locateAction(draft, id);
    return action.name || blockName(action.type);
  } catch {
    return null;
  }
}

/** An abstract block this robot does not map: shown, but marked, in the library. */
function isUnsupported(plugin: Plugin, type: string) {
  const action = abstractAction(type);
  // A sound the robot cannot play is played by the wizard's browser: never unsupported.
  return Boolean(action && !action.runtime && !action.browserFallback && !plugin.abstract?.[type]);
}

function SaveStatus({ save }: { save: SaveState }) {
  const text = {
    saved: "All changes saved",
    saving: "Saving…",
    unsaved: "Unsaved changes",
    conflict: "Not saved: conflict",
    failed: "Not saved",
  }[save.kind];
  return (
    <span
      role="status"
      data-save-state={save.kind}
      className={save.kind === "saved" ? "text-xs text-slate-500" : "text-xs text-amber-800"}
    >
      {text}
    </span>
  );
}

/** The designer's keys: undo/redo, Alt+arrows to move, Delete to remove; never while typing. */
function useDesignerKeys(keys: {
  undo: () => void;
  redo: () => void;
  move: (d: -1 | 1) => void;
  remove: () => void;
  enabled: boolean;
}) {
  useKeys((e) => {
    if (!keys.enabled) return;
    const typing = isTyping(e.target);
    const mod = e.ctrlKey || e.metaKey;
    if (mod && e.key.toLowerCase() === "z" && !typing) {
      e.preventDefault();
      (e.shiftKey ? keys.redo : keys.undo)();
    } else if (mod && e.key.toLowerCase() === "y" && !typing) {
      e.preventDefault();
      keys.redo();
    } else if (e.altKey && (e.key === "ArrowUp" || e.key === "ArrowDown")) {
      e.preventDefault();
      keys.move(e.key === "ArrowUp" ? -1 : 1);
    } else if ((e.key === "Delete" || e.key === "Backspace") && !typing) {
      e.preventDefault();
      keys.remove();
    }
  });
}
