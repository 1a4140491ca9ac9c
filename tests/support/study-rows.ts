// Every row that belongs to one study, by kind: to show that nothing of a
// study was written (its fingerprint before and after) and what a new study
// holds (its counts).
import { sql } from "drizzle-orm";
import type { Database } from "../../src/store/client";

const rowsOf = (studyId: string) => sql`
    select 'study' as t, to_jsonb(s)::text as r from studies s where s.id = ${studyId}
    union all select 'member', to_jsonb(m)::text from study_members m where m.study_id = ${studyId}
    union all select 'experiment', to_jsonb(e)::text from experiments e where e.study_id = ${studyId}
    union all select 'step', to_jsonb(st)::text from steps st join experiments e on e.id = st.experiment_id where e.study_id = ${studyId}
    union all select 'action', to_jsonb(ac)::text from actions ac join steps st on st.id = ac.step_id join experiments e on e.id = st.experiment_id where e.study_id = ${studyId}
    union all select 'version', to_jsonb(v)::text from experiment_versions v join experiments e on e.id = v.experiment_id where e.study_id = ${studyId}
    union all select 'participant', to_jsonb(p)::text from participants p where p.study_id = ${studyId}
    union all select 'condition', to_jsonb(c)::text from conditions c where c.study_id = ${studyId}
    union all select 'session', to_jsonb(se)::text from sessions se where se.study_id = ${studyId}
    union all select 'trial', to_jsonb(tr)::text from trials tr where tr.study_id = ${studyId}
    union all select 'event', to_jsonb(ev)::text from trial_events ev join trials tr on tr.id = ev.trial_id where tr.study_id = ${studyId}
    union all select 'sample', to_jsonb(sa)::text from trial_samples sa join trials tr on tr.id = sa.trial_id where tr.study_id = ${studyId}
    union all select 'annotation', to_jsonb(an)::text from annotations an join trials tr on tr.id = an.trial_id where tr.study_id = ${studyId}
    union all select 'recording', to_jsonb(mr)::text from media_recordings mr join trials tr on tr.id = mr.trial_id where tr.study_id = ${studyId}
    union all select 'questionnaire', to_jsonb(q)::text from questionnaires q where q.study_id = ${studyId}
    union all select 'questionnaire version', to_jsonb(qv)::text from questionnaire_versions qv join questionnaires q on q.id = qv.questionnaire_id where q.study_id = ${studyId}
    union all select 'link', to_jsonb(l)::text from questionnaire_links l where l.study_id = ${studyId}
    union all select 'response', to_jsonb(qr)::text from questionnaire_responses qr join questionnaire_links l on l.id = qr.link_id where l.study_id = ${studyId}
    union all select 'coding scheme', to_jsonb(cs)::text from coding_schemes cs where cs.study_id = ${studyId}
    union all select 'coding scheme version', to_jsonb(cv)::text from coding_scheme_versions cv join coding_schemes cs on cs.id = cv.scheme_id where cs.study_id = ${studyId}
    union all select 'code', to_jsonb(ce)::text from code_events ce join trials tr on tr.id = ce.trial_id where tr.study_id = ${studyId}
    union all select 'audit', to_jsonb(au)::text from audit_log au where au.study_id = ${studyId}`;

/** Every row of the study, as text, in a fixed order: equal before and after means nothing was written. */
export async function studyFingerprint(db: Database, studyId: string): Promise<string> {
  return JSON.stringify(await db.execute(sql`${rowsOf(studyId)} order by 1, 2`));
}

/** How many rows of each kind the study has (kinds with none are left out). */
export async function studyRowCounts(db: Database, studyId: string): Promise<Record<string, number>> {
  const rows = await db.execute<{ t: string; n: number }>(
    sql`select t, count(*)::int as n from (${rowsOf(studyId)}) as rows group by t order by t`,
  );
  return Object.fromEntries(rows.map((r) => [r.t, r.n]));
}
